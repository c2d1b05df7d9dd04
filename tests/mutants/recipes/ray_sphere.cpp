// docs/a0-intersect.md, "Spheres", transcribed literally: graded by
// tests/test_common_mistakes.cpp, it must keep full marks, so the recipe is known to work as
// written (it used to name q / a the near root, which is the far one for a sphere ahead).
// Deliberately not the reference's code.
#include "framework/interface/a0_intersect.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

bool intersectSphere(const Ray& ray, float tMax, const Vec3& centre, float radius, float* t) {
    const Vec3& d = ray.direction;
    Vec3 f = ray.origin - centre;
    float a = glm::dot(d, d);
    // "A zero or NaN direction ... is a miss"
    if (!(a > 0)) return false;
    float c = glm::dot(f, f) - radius * radius;
    // The discriminant from the closest approach: bHalf = -f.d, l = f + (bHalf/a) d.
    float bHalf = -glm::dot(f, d);
    Vec3 l = f + (bHalf / a) * d;
    float discriminant = a * (radius * radius - glm::dot(l, l));
    // "if (!(discriminant >= 0)) it is a miss" (written so that NaN misses too)
    if (!(discriminant >= 0)) return false;
    // q = bHalf + sign(bHalf) sqrt(disc); the roots are q / a and c / q.
    float q = bHalf + std::copysign(std::sqrt(discriminant), bHalf);
    float t0 = 0, t1 = 0;  // "if q is 0, both roots are 0"
    if (q != 0) {
        // "t0 is the smaller of the two, t1 the larger"
        t0 = std::min(q / a, c / q);
        t1 = std::max(q / a, c / q);
    }
    // "t0 if it is inside (tMin, tMax], else t1 if it is, else a miss"
    if (t0 > ray.tMin && t0 <= tMax) {
        *t = t0;
        return true;
    }
    if (t1 > ray.tMin && t1 <= tMax) {
        *t = t1;
        return true;
    }
    return false;
}

}  // namespace rtlab
