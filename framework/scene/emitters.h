// The scene's lights with an area: every triangle and sphere whose material emits
// (docs/conventions.md#lights-and-units). A triangle emits its material's radiance from its
// front face (counter-clockwise seen from the front, normal (p1 - p0) x (p2 - p0)), or from both
// faces when the material is doubleSided; a sphere emits outwards.
#pragma once

#include "framework/scene/scene.h"

#include <vector>

namespace rtlab {

struct Emitter {
    uint32_t prim = 0;       // a triangle or a sphere of the scene
    Vec3 radiance{0.0f};     // [W/(m^2 sr)] per channel
    bool twoSided = false;   // a triangle of a doubleSided material
    double area = 0.0;       // [m^2] of one face
    double power = 0.0;      // [W], the mean over the channels: pi L area, twice that when two-sided
};

// In primitive order; emissive triangles of zero area (they emit nothing) are left out.
std::vector<Emitter> findEmitters(const Scene& scene);

// The radiance primitive prim (hit with geometric normal `normal`, as SurfaceHit stores it)
// sends towards the unit direction `towards`: its material's emission when the emitting side
// faces that way, else zero.
Vec3 emittedRadiance(const Scene& scene, uint32_t prim, const Vec3& normal, const Vec3& towards);

}  // namespace rtlab
