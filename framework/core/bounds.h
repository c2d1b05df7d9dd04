// Axis-aligned bounding box in float. An empty box has lower = +inf and upper = -inf, so a
// union with anything gives that thing.
#pragma once

#include "framework/core/vec.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

struct Bounds3f {
    Vec3 lower{kInfinity};
    Vec3 upper{-kInfinity};

    Bounds3f() = default;
    explicit Bounds3f(const Vec3& p) : lower(p), upper(p) {}
    Bounds3f(const Vec3& a, const Vec3& b) : lower(glm::min(a, b)), upper(glm::max(a, b)) {}

    const Vec3& operator[](int i) const { return i == 0 ? lower : upper; }

    bool isEmpty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
    Vec3 diagonal() const { return upper - lower; }
    Vec3 centre() const { return 0.5f * (lower + upper); }

    // Surface area; 0 for an empty box. Flat boxes have the area of their faces.
    float surfaceArea() const {
        if (isEmpty()) return 0.0f;
        Vec3 d = diagonal();
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }

    // Axis of the largest extent; ties go to the lower axis.
    int longestAxis() const { return maxComponentIndex(diagonal()); }

    void extend(const Vec3& p) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    void extend(const Bounds3f& b) {
        lower = glm::min(lower, b.lower);
        upper = glm::max(upper, b.upper);
    }

    bool contains(const Bounds3f& b) const {
        return b.isEmpty() || (glm::all(glm::lessThanEqual(lower, b.lower)) &&
                               glm::all(glm::greaterThanEqual(upper, b.upper)));
    }
    bool operator==(const Bounds3f&) const = default;
};

// A primitive box a spatial structure (grid, octree, KD-tree) can place: finite and not empty.
// Degenerate input (NaN or infinite vertices) gives boxes that are neither, and such
// primitives go into no cell, node or leaf.
inline bool isPlaceable(const Bounds3f& box) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(box.lower[a]) || !std::isfinite(box.upper[a]) || box.lower[a] > box.upper[a]) return false;
    return true;
}

inline Bounds3f unionOf(Bounds3f a, const Bounds3f& b) {
    a.extend(b);
    return a;
}

}  // namespace rtlab
