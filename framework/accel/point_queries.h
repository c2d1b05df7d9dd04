// Queries along rays that start or end at one point, answered by a structure made for that
// point (docs/performance.md, "The renderer"). A renderer asks its accelerator for one at the
// camera's position and one at each point light (Accelerator::queriesAt); the textbook
// structures make none, fast/'s wide BVHs make a view of the scene from the point
// (fast/point_view.h): POV-Ray 3.6's vista buffer and light buffer.
#pragma once

#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/traversal_stats.h"

namespace rtlab {

class PointQueries {
public:
    virtual ~PointQueries() = default;
    // The answers of the accelerator that made it, for any ray. intersect is fast for a ray
    // that starts at the point; occluded for a ray toward it: direction the point minus the
    // origin, 0 <= tMin and tMax <= 1 (a shadow ray, as spawnShadowRay makes it).
    virtual Hit intersect(const Ray& ray, TraversalStats& stats) const = 0;
    virtual bool occluded(const Ray& ray, TraversalStats& stats) const = 0;
};

}  // namespace rtlab
