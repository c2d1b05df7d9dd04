// The scenes the grader builds its hit-set, structure and stress tests on (docs/grading.md,
// "What is tested"). All but the bunny are generated in code, so the inputs are exact and
// known to the grader without reading a file.
#pragma once

#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::grader {

// Collects triangles (each with its own three vertices unless added as an indexed mesh) and
// spheres into a Scene with one grey material.
class SceneBuilder {
public:
    SceneBuilder();
    void addTriangle(const Vec3& a, const Vec3& b, const Vec3& c);
    // Vertices shared by index, so neighbouring triangles use bit-identical positions.
    void addMesh(const std::vector<Vec3>& positions, const std::vector<std::array<uint32_t, 3>>& indices);
    void addSphere(const Vec3& centre, float radius);
    Scene take() { return std::move(scene_); }

private:
    Scene scene_;
};

// A graded scene: the geometry, a stable identifier (reference data is keyed by it) and, for
// closed meshes, a point inside from which every ray must hit.
struct TestScene {
    std::string id;
    std::string note;  // shown in reports, e.g. why a procedural mesh stands in for the bunny
    Scene scene;
    bool closed = false;
    Vec3 inside{0.0f};
};

// An icosahedron subdivided `levels` times, on the unit sphere: 20 * 4^levels triangles.
TestScene icosphere(int levels);
// count random triangles in the unit cube (sizes 0.01 .. 0.2) and a few spheres.
TestScene triangleSoup(int count, uint64_t seed);
// An axis-aligned room of quads on dyadic planes with two boxes and two spheres inside:
// flat leaf boxes and shared edges on slab planes everywhere.
TestScene cornellBox();
// A flat scene: 16 x 8 squares of side 0.25, two triangles each, in the plane z = 0. Every box has
// zero width in z: one grid cell thick, KD-tree nodes of zero width (stress catalogue GRID-06).
TestScene flatScene();
// modelsDir/bunny.gltf when it exists and loads; otherwise a bumpy closed sphere, with a note.
TestScene bunnyOrStandIn(const std::string& modelsDir);

// The "teapot in a stadium" (Haines): the bunny (or its stand-in) scaled to size 1 at the origin
// inside a closed box of side 200, where one resolution for the whole scene fails a grid.
TestScene teapotInAStadium(const std::string& modelsDir);

// The three procedural scenes and the bunny (or its stand-in).
std::vector<TestScene> hitSetScenes(const std::string& modelsDir);

}  // namespace rtlab::grader
