// The per-query context an accelerator's traversal works through. It owns the ray, its
// precomputed slab data and the work counters, so every node visit and primitive test is
// counted by the framework, whoever wrote the traversal.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/accel/traversal_stats.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

class Traversal {
public:
    Traversal(const PrimitiveSet& primitives, const Ray& ray, TraversalStats& stats)
        : primitives_(primitives), ray_(ray), inverse_(ray), stats_(stats) {
        ++stats_.rays;
    }

    const Ray& ray() const { return ray_; }
    // Direction sign per axis (1 = negative, -0.0 included): decides the near child.
    const std::array<int, 3>& dirIsNegative() const { return inverse_.dirIsNegative; }

    // One node visit: does the ray's segment (tMin, tMax] touch the box? *tEnter receives
    // the entry distance, which ordered traversals use to skip far children.
    bool hitsBox(const Bounds3f& box, float tMax, float* tEnter) {
        ++stats_.nodeVisits;
        return intersectBox(box, inverse_, ray_.tMin, tMax, tEnter);
    }

    // One primitive test for a closest-hit query: updates hit when prim is hit in
    // (tMin, hit.t].
    bool intersect(uint32_t prim, Hit& hit) {
        ++stats_.primitiveTests;
        return primitives_.intersect(prim, ray_, hit);
    }

    // One primitive test for an any-hit query: does prim block the segment (tMin, tMax]?
    bool occludes(uint32_t prim) {
        ++stats_.primitiveTests;
        Hit hit;
        hit.t = ray_.tMax;
        return primitives_.intersect(prim, ray_, hit);
    }

private:
    const PrimitiveSet& primitives_;
    const Ray& ray_;
    RayInverse inverse_;
    TraversalStats& stats_;
};

}  // namespace rtlab
