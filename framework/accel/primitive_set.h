// The primitives an accelerator is built over, addressed by index: bounds and centroid for
// building, intersection for traversal. Triangle vertices are gathered contiguously so a leaf
// reads one cache line per triangle instead of chasing indices.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/scene/scene.h"

#include <array>
#include <span>
#include <vector>

namespace rtlab {

class PrimitiveSet {
public:
    explicit PrimitiveSet(const Scene& scene);

    uint32_t size() const { return static_cast<uint32_t>(bounds_.size()); }
    const Bounds3f& bounds(uint32_t prim) const { return bounds_[prim]; }
    // Every primitive's bounds, indexed by primitive id.
    std::span<const Bounds3f> allBounds() const { return bounds_; }
    Vec3 centroid(uint32_t prim) const { return bounds_[prim].centre(); }

    // Triangles come first (ids 0 .. triangleCount()-1), spheres after them.
    uint32_t triangleCount() const { return static_cast<uint32_t>(triangles_.size()); }
    const std::array<Vec3, 3>& triangle(uint32_t prim) const { return triangles_[prim]; }
    std::span<const std::array<Vec3, 3>> allTriangles() const { return triangles_; }

    // Closest-hit step: tests primitive prim against (ray.tMin, hit.t]; on a hit, overwrites
    // hit and returns true.
    bool intersect(uint32_t prim, const Ray& ray, Hit& hit) const;

private:
    std::vector<std::array<Vec3, 3>> triangles_;
    std::vector<Sphere> spheres_;
    std::vector<Bounds3f> bounds_;
};

}  // namespace rtlab
