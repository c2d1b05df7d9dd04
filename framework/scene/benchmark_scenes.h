// The procedural benchmark meshes of docs/performance.md#scene-definitions, generated bit for
// bit as specified there (this file's .cpp is compiled with -ffp-contract=off), and the
// benchmark viewpoint that every benchmark scene shares (docs/performance.md#ray-sets,
// primary rays).
#pragma once

#include "framework/core/bounds.h"
#include "framework/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

// An indexed triangle mesh in world space, the form the reference page describes.
struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> indices;

    Bounds3f bounds() const;
};

// Haines's "teapot in a stadium": the model's triangles scaled to a longest extent of 1 and
// centred at the origin, inside a closed box of side 200 whose kStadiumWallTriangles triangles
// come last. One resolution for the whole box fails a uniform grid here.
TriangleMesh teapotInAStadium(const Scene& model);
inline constexpr uint32_t kStadiumWallTriangles = 12;

// 7,381 spheres (recursion depth 4, 9 children of a third of the radius each) of 144
// triangles: 1,062,864 triangles.
TriangleMesh makeSphereflake();

// 2^20 small triangles (edge ~0.02) with centres uniform in [0,1)^3, from PCG32 seed 7 on
// stream 54: a stress case with heavy overlap.
TriangleMesh makeRandomSoup();

inline constexpr uint32_t kSphereflakeTriangles = 1'062'864;
inline constexpr uint32_t kRandomSoupTriangles = 1u << 20;

// The names `rtlab scene generate` accepts: "sphereflake", "randsoup".
const std::vector<std::string>& generatedSceneNames();

// The scene of a generated mesh: the mesh with one white Lambert material, the benchmark
// camera (benchmarkView) and one point light beside it, so that it renders as is. Throws
// rtlab::Error naming the valid names for an unknown name.
Scene makeGeneratedScene(const std::string& name);

// A generated scene when nameOrPath is one of generatedSceneNames(), else loadGltf(nameOrPath).
Scene loadOrGenerateScene(const std::string& nameOrPath);

// A renderable scene around any mesh (same material, camera and light as above), the camera
// framing viewBounds (the mesh's own bounds unless given).
Scene sceneFromMesh(TriangleMesh mesh, const std::string& sourcePath);
Scene sceneFromMesh(TriangleMesh mesh, const std::string& sourcePath, const Bounds3f& viewBounds);

// The teapot in a stadium as a scene that renders: the camera and light frame the model, as the
// benchmark's rays do, not the stadium's box (`rtlab scene generate stadium --model FILE`).
Scene makeStadiumScene(const Scene& model);

// FNV-1a 64 over the 9 floats of every triangle in index order (docs/performance.md#checksums).
uint64_t triangleChecksum(const Scene& scene);

}  // namespace rtlab
