// Shadow rays toward one point, answered by a structure made for that point (docs/performance.md,
// "The renderer"). A renderer asks its accelerator for one per point light
// (Accelerator::occluderToward); the textbook structures make none, fast/'s wide BVHs make a
// light buffer (fast/light_buffer.h).
#pragma once

#include "framework/core/ray.h"
#include "framework/interface/traversal_stats.h"

namespace rtlab {

class PointOccluder {
public:
    virtual ~PointOccluder() = default;
    // The answer of occluded() of the accelerator that made it, for any ray; fast for a ray
    // whose direction is the point minus its origin, with 0 <= tMin and tMax <= 1 (the
    // segment from the origin toward the point, as spawnShadowRay makes it).
    virtual bool occluded(const Ray& ray, TraversalStats& stats) const = 0;
};

}  // namespace rtlab
