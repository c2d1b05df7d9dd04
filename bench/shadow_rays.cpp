#include "bench/shadow_rays.h"

#include <cmath>

namespace rtlab::bench {

std::vector<BenchSegment> makeShadowRays(std::span<const BenchRay> primary, std::span<const TraceResult> hits,
                                         const Bounds3f& bounds) {
    Vec3 light = bounds.centre() + glm::length(bounds.diagonal()) * glm::normalize(Vec3(-0.6f, 1.0f, 0.4f));
    std::vector<BenchSegment> segments;
    for (size_t i = 0; i < primary.size() && i < hits.size(); ++i) {
        if (hits[i].prim == kNoHit) continue;
        Vec3 point = primary[i].origin + (hits[i].t * (1.0f - 1e-4f)) * primary[i].direction;
        Vec3 toLight = light - point;
        float distance = glm::length(toLight);
        segments.push_back({point, toLight / distance, distance});
    }
    return segments;
}

}  // namespace rtlab::bench
