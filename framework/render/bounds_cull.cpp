#include "framework/render/bounds_cull.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

BoundsCull::BoundsCull(const CameraFilm& film, const Bounds3f& sceneBounds) : film_(film) {
    if (sceneBounds.isEmpty()) {  // no primitive: every ray misses
        mode_ = Mode::Always;
        return;
    }
    const DVec3 origin(film.origin);
    DVec3 lower = DVec3(sceneBounds.lower) - origin, upper = DVec3(sceneBounds.upper) - origin;
    double reach = 0.0;
    for (int axis = 0; axis < 3; ++axis) reach = std::max({reach, std::abs(lower[axis]), std::abs(upper[axis])});
    const double margin = 1e-5 * std::sqrt(3.0) * reach;  // at least 1e-5 of the far corner's distance
    lower -= margin;
    upper += margin;
    bool inside = true;
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(lower[axis]) || !std::isfinite(upper[axis])) return;  // Mode::Never
        inside = inside && lower[axis] <= 0.0 && upper[axis] >= 0.0;
    }
    if (inside) return;
    for (int i = 0; i < 8; ++i)
        corners_[i] = DVec3(i & 1 ? upper.x : lower.x, i & 2 ? upper.y : lower.y, i & 4 ? upper.z : lower.z);
    mode_ = Mode::Test;
}

BoundsCull::Row BoundsCull::row(int y) const {
    Row row;
    row.mode_ = mode_;
    row.all_ = mode_ == Mode::Always;
    if (mode_ != Mode::Test) return row;
    // The direction through (x, y + 0.5) is a + x * b; the row's plane has normal n.
    const DVec3 a = film_.column(0.0) + film_.row(y + 0.5), b = film_.right / film_.width;
    const DVec3 n = glm::cross(a, b);
    // The plane through the ray at x normal to the row's plane has normal cross(n, a + x b):
    // a corner's side is linear in x. A zero n (a degenerate film) makes every product 0, and
    // nothing is skipped.
    const DVec3 na = glm::cross(n, a), nb = glm::cross(n, b);
    int above = 0, below = 0;
    for (int c = 0; c < 8; ++c) {
        double side = glm::dot(n, corners_[c]);
        above += side > 0.0;
        below += side < 0.0;
        row.offset_[c] = glm::dot(na, corners_[c]);
        row.slope_[c] = glm::dot(nb, corners_[c]);
    }
    row.all_ = above == 8 || below == 8;
    return row;
}

bool BoundsCull::Row::misses(double x0, double x1) const {
    if (mode_ != Mode::Test || all_) return all_;
    bool left = true, right = true;
    for (int c = 0; c < 8; ++c) {
        left = left && offset_[c] + x0 * slope_[c] < 0.0;
        right = right && offset_[c] + x1 * slope_[c] > 0.0;
    }
    return left || right;
}

}  // namespace rtlab
