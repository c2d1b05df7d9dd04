// Assignment a0, part 1: the slab test.            Guide: docs/a0-intersect.md#slab-test
//
// Contract (framework/interface/a0_intersect.h):
//   Return true when the ray's segment (tMin, tMax] overlaps the closed box, and write the
//   entry distance (never below tMin) to *tEnter.
//
// Hints:
//   * ray.invDirection holds 1/direction; ray.dirIsNegative[axis] says which face
//     (box[0] = lower, box[1] = upper) the ray meets first on that axis.
//   * A zero direction component makes invDirection infinite, and 0 * inf is NaN when the
//     origin lies on a face plane. Write your min/max so that NaN leaves tMin/tMax unchanged.
//   * Multiply the far distance by 1 + 2 * gamma(3) (framework/core/float_bits.h).
//   * Boxes may be flat (zero thickness): compare with <=, not <.
#include "framework/core/error.h"
#include "framework/core/float_bits.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

bool intersectBox(const Bounds3f& box, const RayInverse& ray, float tMin, float tMax, float* tEnter) {
    (void)box, (void)ray, (void)tMin, (void)tMax, (void)tEnter;
    throw NotImplemented("a0 intersectBox (assignments/a0_intersect/ray_box.cpp)");
}

}  // namespace rtlab
