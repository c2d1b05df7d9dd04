#include "grader/a4_octree/octree_oracle.h"

#include <algorithm>
#include <cmath>

namespace rtlab::grader {
namespace {

// Relative size of the band in which a float test may decide a contact either way: a float
// separating-axis test loses a few ulps (6e-8 relative) in each of its few operations.
constexpr double kRelativeSlack = 1e-5;

struct DBox {
    DVec3 lower, upper;
};

// Separated on this axis when the triangle's projection ends before the box's begins (or the
// reverse); touching is not separated. The box's projection, without moving it to the origin.
bool separatedOn(const DVec3& axis, const std::array<DVec3, 3>& v, const DBox& box) {
    double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
    double lo = std::min({p0, p1, p2}), hi = std::max({p0, p1, p2});
    double boxLo = 0.0, boxHi = 0.0;
    for (int a = 0; a < 3; ++a) {
        double x = axis[a] * box.lower[a], y = axis[a] * box.upper[a];
        boxLo += std::min(x, y);
        boxHi += std::max(x, y);
    }
    return hi < boxLo || lo > boxHi;
}

bool overlapsInDouble(const std::array<DVec3, 3>& v, const DBox& box) {
    for (int a = 0; a < 3; ++a)
        if (box.lower[a] > box.upper[a]) return false;  // shrunk past its thickness
    const DVec3 axes[3] = {DVec3(1, 0, 0), DVec3(0, 1, 0), DVec3(0, 0, 1)};
    const DVec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    for (const DVec3& axis : axes)
        if (separatedOn(axis, v, box)) return false;
    for (const DVec3& edge : edges)
        for (const DVec3& axis : axes)
            if (separatedOn(glm::cross(edge, axis), v, box)) return false;
    return !separatedOn(glm::cross(edges[0], edges[1]), v, box);
}

}  // namespace

double overlapSlack(const Bounds3f& box) {
    double scale = 0.0;
    for (int a = 0; a < 3; ++a)
        scale = std::max({scale, std::abs(double(box.lower[a])), std::abs(double(box.upper[a])),
                          double(box.upper[a]) - double(box.lower[a])});
    return kRelativeSlack * scale;
}

Overlap triangleBoxOverlap(const std::array<Vec3, 3>& triangle, const Bounds3f& box, double slack) {
    std::array<DVec3, 3> v{DVec3(triangle[0]), DVec3(triangle[1]), DVec3(triangle[2])};
    for (const DVec3& p : v)
        if (glm::any(glm::isnan(p))) return Overlap::No;
    DBox grown{DVec3(box.lower) - slack, DVec3(box.upper) + slack};
    if (!overlapsInDouble(v, grown)) return Overlap::No;
    DBox shrunk{DVec3(box.lower) + slack, DVec3(box.upper) - slack};
    return overlapsInDouble(v, shrunk) ? Overlap::Yes : Overlap::Unsure;
}

bool boxesOverlap(const Bounds3f& a, const Bounds3f& b) {
    for (int axis = 0; axis < 3; ++axis)
        if (!(a.lower[axis] <= b.upper[axis] && a.upper[axis] >= b.lower[axis])) return false;
    return true;
}

Bounds3f expectedRootBox(const Bounds3f& bounds) {
    if (bounds.isEmpty()) return Bounds3f(Vec3(0.0f));
    Vec3 extent = bounds.upper - bounds.lower;
    float half = 0.5f * std::max({extent.x, extent.y, extent.z});
    Vec3 centre = 0.5f * (bounds.lower + bounds.upper);
    Bounds3f root;
    root.lower = glm::min(centre - half, bounds.lower);
    root.upper = glm::max(centre + half, bounds.upper);
    return root;
}

Bounds3f expectedChildBox(const Bounds3f& box, int child) {
    Vec3 mid = 0.5f * (box.lower + box.upper);
    Bounds3f result;
    for (int a = 0; a < 3; ++a) {
        bool upper = (child >> (2 - a)) & 1;
        result.lower[a] = upper ? mid[a] : box.lower[a];
        result.upper[a] = upper ? box.upper[a] : mid[a];
    }
    return result;
}

}  // namespace rtlab::grader
