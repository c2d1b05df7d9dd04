// Reference solution: Akenine-Moller's separating-axis test for a triangle and a box
// (docs/a4-octree.md#triangle-and-box).
#include "framework/interface/a4_octree.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

// True when the axis separates the triangle (vertices v, relative to the box's centre) from
// the box of half-size h: the projections are disjoint with a gap. Written so that NaN
// separates, and so that touching projections (min == r) do not.
bool separates(const Vec3& axis, const std::array<Vec3, 3>& v, const Vec3& h) {
    float p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
    float lo = std::min({p0, p1, p2}), hi = std::max({p0, p1, p2});
    float r = h.x * std::abs(axis.x) + h.y * std::abs(axis.y) + h.z * std::abs(axis.z);
    return !(lo <= r && hi >= -r);
}

}  // namespace

bool triangleOverlapsBox(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3f& box) {
    // min and max skip a NaN projection instead of spreading it, so NaN is refused up front.
    if (glm::any(glm::isnan(p0)) || glm::any(glm::isnan(p1)) || glm::any(glm::isnan(p2))) return false;
    // Centring the box at the origin makes its projection on any axis symmetric: [-r, r].
    Vec3 c = box.centre(), h = 0.5f * box.diagonal();
    std::array<Vec3, 3> v{p0 - c, p1 - c, p2 - c};
    std::array<Vec3, 3> edges{v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    const Vec3 boxAxes[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    // The box normals first: they are the bounding-box test, and reject most pairs cheaply.
    for (const Vec3& axis : boxAxes)
        if (separates(axis, v, h)) return false;
    // The nine edge-axis cross products. An edge parallel to a box axis gives the zero vector,
    // whose projections are all 0 = r: never separating, as it must be.
    for (const Vec3& edge : edges)
        for (const Vec3& axis : boxAxes)
            if (separates(glm::cross(edge, axis), v, h)) return false;
    // The triangle's own plane; zero for a degenerate triangle, which the axes above decide.
    return !separates(glm::cross(edges[0], edges[1]), v, h);
}

}  // namespace rtlab
