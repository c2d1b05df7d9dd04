// Reference solution: the pieces of Revelles, Urena and Lastra's parametric octree walk
// (docs/a4-octree.md#the-parametric-walk).
#include "framework/interface/a4_octree.h"

#include <cmath>

namespace rtlab {

MirroredRay mirrorRay(const Bounds3f& root, const Ray& ray) {
    MirroredRay m{ray, 0};
    for (int axis = 0; axis < 3; ++axis) {
        // signbit, so that -0.0 is mirrored too: 1 / -0.0 = -inf points the same way as a
        // negative component, and the walk below assumes no component does.
        if (!std::signbit(ray.direction[axis])) continue;
        // Mirroring about the root's centre maps the root onto itself.
        m.ray.origin[axis] = (root.lower[axis] + root.upper[axis]) - ray.origin[axis];
        m.ray.direction[axis] = -ray.direction[axis];
        m.mask |= 4 >> axis;
    }
    return m;
}

NodeSpan rootSpan(const Bounds3f& root, const Ray& mirrored) {
    NodeSpan span;
    for (int axis = 0; axis < 3; ++axis) {
        float o = mirrored.origin[axis], d = mirrored.direction[axis];
        if (d == 0.0f) {
            // A ray parallel to the slab is in it for every t or for none; dividing would give
            // 0 / 0 = NaN for an origin on a face, which the closed slab includes.
            span.t0[axis] = o < root.lower[axis] ? kInfinity : -kInfinity;
            span.t1[axis] = o > root.upper[axis] ? -kInfinity : kInfinity;
        } else {
            span.t0[axis] = (root.lower[axis] - o) / d;
            span.t1[axis] = (root.upper[axis] - o) / d;
        }
    }
    return span;
}

Vec3 midParameters(const Ray& mirrored, const NodeSpan& span, const Bounds3f& box) {
    Vec3 tm = 0.5f * (span.t0 + span.t1);
    int side = childIndex(mirrored.origin, box.centre());
    for (int axis = 0; axis < 3; ++axis)
        // Parallel to the axis, the ray never crosses the mid-plane: it stays in the half its
        // origin is in. -inf puts the crossing before everything (the upper half from the
        // start), +inf after everything (the lower half for good).
        if (mirrored.direction[axis] == 0.0f) tm[axis] = (side & (4 >> axis)) ? -kInfinity : kInfinity;
    return tm;
}

int firstNode(const Vec3& t0, const Vec3& tm) {
    // The ray enters the node through the plane it crosses last: the largest t0. `>=` hands a
    // tie to the higher axis, as nextNode does.
    int entry = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (t0[axis] >= t0[entry]) entry = axis;
    // On the entry face, the ray is in the upper half of another axis if it crossed that axis's
    // mid-plane before entering.
    int child = 0;
    for (int axis = 0; axis < 3; ++axis)
        if (axis != entry && tm[axis] < t0[entry]) child |= 4 >> axis;
    return child;
}

int nextNode(int current, const Vec3& t1) {
    // The ray leaves the child through the plane it reaches first; `<=` hands ties to the
    // higher axis.
    int exit = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (t1[axis] <= t1[exit]) exit = axis;
    int bit = 4 >> exit;
    // Already in the upper half on that axis: the exit plane is the parent's own face.
    return (current & bit) ? kOctreeEnd : (current | bit);
}

}  // namespace rtlab
