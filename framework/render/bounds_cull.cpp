#include "framework/render/bounds_cull.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

std::vector<Bounds3f> sceneBoxes(const Scene& scene) {
    const Vec3 centre = scene.bounds().centre();
    std::array<Bounds3f, 8> octants;
    for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim) {
        Bounds3f box = scene.primitiveBounds(prim);
        Vec3 c = box.centre();
        octants[(c.x > centre.x) + 2 * (c.y > centre.y) + 4 * (c.z > centre.z)].extend(box);
    }
    std::vector<Bounds3f> boxes;
    for (const Bounds3f& box : octants)
        if (!box.isEmpty()) boxes.push_back(box);
    return boxes;
}

BoundsCull::BoundsCull(const CameraFilm& film, std::span<const Bounds3f> boxes) : film_(film) {
    const DVec3 origin(film.origin);
    for (const Bounds3f& bounds : boxes) {
        if (bounds.isEmpty()) continue;
        Box& box = boxes_.emplace_back();
        DVec3 lower = DVec3(bounds.lower) - origin, upper = DVec3(bounds.upper) - origin;
        double reach = 0.0;
        for (int axis = 0; axis < 3; ++axis) reach = std::max({reach, std::abs(lower[axis]), std::abs(upper[axis])});
        const double margin = 1e-5 * std::sqrt(3.0) * reach;  // at least 1e-5 of the far corner's distance
        lower -= margin;
        upper += margin;
        bool inside = true;
        for (int axis = 0; axis < 3; ++axis) {
            box.never = box.never || !std::isfinite(lower[axis]) || !std::isfinite(upper[axis]);
            inside = inside && lower[axis] <= 0.0 && upper[axis] >= 0.0;
        }
        box.never = box.never || inside;
        for (int i = 0; i < 8; ++i)
            box.corners[i] = DVec3(i & 1 ? upper.x : lower.x, i & 2 ? upper.y : lower.y, i & 4 ? upper.z : lower.z);
    }
}

BoundsCull::Row BoundsCull::row(int y) const {
    // The direction through (x, y + 0.5) is a + x * b; the row's plane has normal n.
    const DVec3 a = film_.column(0.0) + film_.row(y + 0.5), b = film_.right / film_.width;
    const DVec3 n = glm::cross(a, b);
    // The plane through the ray at x normal to the row's plane has normal cross(n, a + x b):
    // a corner's side is linear in x. A zero n (a degenerate film) makes every product 0, and
    // nothing is skipped.
    const DVec3 na = glm::cross(n, a), nb = glm::cross(n, b);
    Row row;
    for (const Box& box : boxes_) {
        Row::Side& side = row.boxes_.emplace_back();
        side.never = box.never;
        int above = 0, below = 0;
        for (int c = 0; c < 8; ++c) {
            double height = glm::dot(n, box.corners[c]);
            above += height > 0.0;
            below += height < 0.0;
            side.offset[c] = glm::dot(na, box.corners[c]);
            side.slope[c] = glm::dot(nb, box.corners[c]);
        }
        side.outOfRow = above == 8 || below == 8;
    }
    return row;
}

bool BoundsCull::Row::misses(double x0, double x1) const {
    for (const Side& box : boxes_) {
        if (box.never) return false;
        if (box.outOfRow) continue;
        bool left = true, right = true;
        for (int c = 0; c < 8; ++c) {
            left = left && box.offset[c] + x0 * box.slope[c] < 0.0;
            right = right && box.offset[c] + x1 * box.slope[c] > 0.0;
        }
        if (!left && !right) return false;
    }
    return true;
}

}  // namespace rtlab
