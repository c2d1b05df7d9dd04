// Assignment a4, part 1: does a triangle overlap a box?   Guide: docs/a4-octree.md#triangle-and-box
//
// Contract (framework/interface/a4_octree.h):
//   triangleOverlapsBox: true when the closed triangle p0 p1 p2 and the closed box share a
//   point. Separating axes (Akenine-Moller 2001): the three box normals x, y, z; the nine
//   cross products e_i x axis of the edges e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2 with the box
//   axes; the triangle's normal e0 x e1. The triangle is separated (return false) as soon as,
//   on one axis, its projection and the box's projection are disjoint with a gap between
//   them: touching is overlapping. NaN anywhere returns false.
//
// Hints:
//   * Move everything to the box's centre c first: with v_i = p_i - c and half-size
//     h = 0.5 * (upper - lower), the box projects onto axis a as [-r, r] with
//     r = h.x |a.x| + h.y |a.y| + h.z |a.z|.
//   * The test is "separated if min > r or max < -r": `>`, not `>=`. A triangle lying in a
//     face of the box, or touching it with a vertex, must overlap it.
//   * An edge parallel to a box axis gives the axis (0, 0, 0): min = max = r = 0, nothing is
//     separated. A degenerate triangle (a segment) has the normal (0, 0, 0): same, and its
//     edges' axes still do the work.
//   * NaN fails every comparison, so write the tests so that a failed comparison separates:
//     `if (!(min <= r && max >= -r)) return false;`.
#include "framework/core/error.h"
#include "framework/interface/a4_octree.h"

namespace rtlab {

bool triangleOverlapsBox(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3f& box) {
    (void)p0, (void)p1, (void)p2, (void)box;
    throw NotImplemented("a4 triangleOverlapsBox (assignments/a4_octree/triangle_box.cpp)");
}

}  // namespace rtlab
