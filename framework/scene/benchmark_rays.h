// The benchmark ray sets of docs/performance.md#ray-sets, generated bit for bit (this
// file's .cpp is compiled with -ffp-contract=off): 1024x1024 primary rays from a fixed
// viewpoint and 2^20 incoherent rays starting inside the scene's bounds. All rays have
// tMin = 0, tMax = +inf and unit-length directions.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"
#include "framework/scene/camera.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rtlab {

// The viewpoint of the primary rays, derived from the scene's bounds: looking at the centre
// from direction (0.6, 0.5, 1.0) at twice the bounding sphere's radius, 45 degree vertical
// field of view, square image.
struct BenchmarkView {
    Vec3 eye;
    Vec3 forward;
    Vec3 right;
    Vec3 up;
    float tanHalfFov;  // tan(22.5 degrees)

    explicit BenchmarkView(const Bounds3f& bounds);

    // The same view as a glTF-style camera, for the generated scenes and the renderer.
    Camera camera() const;
};

inline constexpr int kPrimaryResolution = 1024;
inline constexpr uint32_t kIncoherentRayCount = 1u << 20;

// One ray through the centre of each pixel of a resolution x resolution image, row-major from
// the top-left pixel.
std::vector<Ray> makePrimaryRays(const Bounds3f& bounds, int resolution = kPrimaryResolution);

// Origins uniform in the bounds, directions uniform on the sphere; PCG32 seed 1234, stream 54,
// five draws per ray (origin x, y, z, then z and azimuth of the direction).
std::vector<Ray> makeIncoherentRays(const Bounds3f& bounds, uint32_t count = kIncoherentRayCount);

enum class RayKind { Primary, Incoherent };

// "primary" or "incoherent"; throws rtlab::Error for anything else.
RayKind parseRayKind(const std::string& name);
const char* rayKindName(RayKind kind);
std::vector<Ray> makeBenchmarkRays(RayKind kind, const Bounds3f& bounds);

// FNV-1a 64 over {origin.xyz, direction.xyz} (24 bytes) of every ray.
uint64_t rayChecksum(std::span<const Ray> rays);

}  // namespace rtlab
