// Reference solution: robust ray-sphere intersection (docs/a0-intersect.md).
#include "framework/interface/a0_intersect.h"

#include <cmath>
#include <utility>

namespace rtlab {

bool intersectSphere(const Ray& ray, float tMax, const Vec3& centre, float radius, float* t) {
    const Vec3& d = ray.direction;
    float a = glm::dot(d, d);
    if (!(a > 0.0f)) return false;
    Vec3 f = ray.origin - centre;
    float bHalf = -glm::dot(f, d);
    // Discriminant from the squared distance between the centre and the ray's closest point,
    // not from b^2 - 4ac, which cancels catastrophically for distant or small spheres.
    Vec3 closest = f + (bHalf / a) * d;
    float discriminant = a * (radius * radius - glm::dot(closest, closest));
    if (!(discriminant >= 0.0f)) return false;
    // The stable pair of quadratic roots (no subtraction of nearly equal numbers).
    float q = bHalf + std::copysign(std::sqrt(discriminant), bHalf);
    float c = glm::dot(f, f) - radius * radius;
    float t0 = q / a;
    float t1 = q != 0.0f ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    float nearest = (t0 > ray.tMin && t0 <= tMax) ? t0 : t1;
    if (!(nearest > ray.tMin && nearest <= tMax)) return false;
    *t = nearest;
    return true;
}

}  // namespace rtlab
