// Random and structured rays for hit-set tests (docs/grading.md, "Hit sets"): random rays
// through the scene, axis-aligned rays with +0/-0 components lying in vertex planes, rays aimed
// at edges and vertices, grazing rays and rays from inside. Fixed seeds unless --seed.
#pragma once

#include "framework/core/ray.h"
#include "grader/kit/test_scenes.h"

#include <cstdint>
#include <vector>

namespace rtlab::grader {

enum class RayKind : uint8_t { Random, AxisAligned, Edge, Vertex, Grazing, Inside };
const char* rayKindName(RayKind kind);

struct RaySet {
    std::vector<Ray> rays;
    std::vector<RayKind> kinds;
    // 1 where the ray certainly crosses a surface: from inside a closed mesh, or through a
    // manifold edge that is not a silhouette. A watertight implementation hits these.
    std::vector<uint8_t> mustHit;
};

RaySet makeRaySet(const TestScene& scene, int count, uint64_t seed);

// The same rays with tMax cut at a random distance, for any-hit queries.
std::vector<Ray> withRandomTMax(const std::vector<Ray>& rays, const Scene& scene, uint64_t seed);

}  // namespace rtlab::grader
