// Assignment a4, part 3: the parametric walk's pieces.   Guide: docs/a4-octree.md#the-parametric-walk
//
// Contract (framework/interface/a4_octree.h):
//   * mirrorRay(root, ray): per axis a with std::signbit(d[a]): o[a] = (root.lower[a] +
//     root.upper[a]) - o[a], d[a] = -d[a], mask |= 4 >> a.
//   * rootSpan(root, mirrored): per axis, d != 0: t0 = (root.lower - o) / d,
//     t1 = (root.upper - o) / d; d == 0: t0 = o < lower ? +inf : -inf,
//     t1 = o > upper ? -inf : +inf.
//   * midParameters(mirrored, span, box): tm = 0.5f * (t0 + t1), except where d == 0:
//     tm = (childIndex(o, box.centre()) has the axis's bit) ? -inf : +inf.
//   * firstNode(t0, tm): entry axis = argmax t0, ties to the higher axis; set the bit of each
//     other axis b with tm[b] < t0[entry].
//   * nextNode(current, t1): exit axis = argmin t1, ties to the higher axis; kOctreeEnd if
//     current has that bit, else current | bit.
//
// Hints:
//   * Mirror about the root's centre: (lower + upper) - o. `upper - o` (mirroring about the
//     size) is right only for an octree whose box starts at the origin.
//   * std::signbit, not d < 0: -0.0 < 0 is false, but 1 / -0.0 is -inf.
//   * Revelles' paper printed Table 1 with x and z swapped (the authors' erratum): x is bit 4,
//     z is bit 1, everywhere.
//   * On an axis the ray runs parallel to, 0.5 * (t0 + t1) is 0.5 * (-inf + inf) = NaN, and
//     every comparison with NaN is false: that is why the parallel rule exists.
#include "framework/core/error.h"
#include "framework/interface/a4_octree.h"

namespace rtlab {

MirroredRay mirrorRay(const Bounds3f& root, const Ray& ray) {
    (void)root, (void)ray;
    throw NotImplemented("a4 mirrorRay (assignments/a4_octree/octree_walk.cpp)");
}

NodeSpan rootSpan(const Bounds3f& root, const Ray& mirrored) {
    (void)root, (void)mirrored;
    throw NotImplemented("a4 rootSpan (assignments/a4_octree/octree_walk.cpp)");
}

Vec3 midParameters(const Ray& mirrored, const NodeSpan& span, const Bounds3f& box) {
    (void)mirrored, (void)span, (void)box;
    throw NotImplemented("a4 midParameters (assignments/a4_octree/octree_walk.cpp)");
}

int firstNode(const Vec3& t0, const Vec3& tm) {
    (void)t0, (void)tm;
    throw NotImplemented("a4 firstNode (assignments/a4_octree/octree_walk.cpp)");
}

int nextNode(int current, const Vec3& t1) {
    (void)current, (void)t1;
    throw NotImplemented("a4 nextNode (assignments/a4_octree/octree_walk.cpp)");
}

}  // namespace rtlab
