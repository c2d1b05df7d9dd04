// docs/a0-intersect.md, "Slab test", transcribed step by step and nothing more: graded by
// tests/test_common_mistakes.cpp, it must keep full marks, so the recipe is known to work as
// written. Deliberately not the reference's code (which exits early per axis).
#include "framework/core/float_bits.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

bool intersectBox(const Bounds3f& box, const RayInverse& ray, float tMin, float tMax, float* tEnter) {
    for (int a = 0; a < 3; ++a) {
        // "pick the near plane, box[dirIsNegative[a]], and the far one, box[1 - dirIsNegative[a]]"
        float tNear = (box[ray.dirIsNegative[a]][a] - ray.origin[a]) * ray.invDirection[a];
        float tFar = (box[1 - ray.dirIsNegative[a]][a] - ray.origin[a]) * ray.invDirection[a];
        // 3. "Multiply tFar by 1 + 2 * gamma(3) before using it."
        tFar *= 1 + 2 * gamma(3);
        // 1. "Write the interval update so that NaN is ignored"
        tMin = tNear > tMin ? tNear : tMin;
        tMax = tFar < tMax ? tFar : tMax;
    }
    // 2. "The final test is tMin <= tMax (return false only when tMin > tMax)."
    if (tMin > tMax) return false;
    // "Write the entry distance, never below tMin, to *tEnter"
    *tEnter = tMin;
    return true;
}

}  // namespace rtlab
