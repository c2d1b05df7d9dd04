// Reference solution: the slab test (docs/a0-intersect.md).
#include "framework/core/float_bits.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

bool intersectBox(const Bounds3f& box, const RayInverse& ray, float tMin, float tMax, float* tEnter) {
    for (int axis = 0; axis < 3; ++axis) {
        // The sign of the direction picks which face is entered first; -0.0 counts as negative,
        // consistently with invDirection = -inf.
        int nearSide = ray.dirIsNegative[axis];
        float tNear = (box[nearSide][axis] - ray.origin[axis]) * ray.invDirection[axis];
        float tFar = (box[1 - nearSide][axis] - ray.origin[axis]) * ray.invDirection[axis];
        // Enlarge the far distance by the rounding error of the three operations above
        // (Ize 2013), so a box the ray touches is never lost.
        tFar *= 1.0f + 2.0f * gamma(3);
        // Written so that NaN (0 * inf: origin on a face plane, direction component 0) leaves
        // the interval unchanged instead of poisoning it.
        tMin = tNear > tMin ? tNear : tMin;
        tMax = tFar < tMax ? tFar : tMax;
        if (tMin > tMax) return false;
    }
    *tEnter = tMin;
    return true;
}

}  // namespace rtlab
