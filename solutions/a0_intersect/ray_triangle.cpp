// Reference solution: watertight ray-triangle intersection (Woop, Benthin, Wald 2013) with
// sign-exact edge functions (docs/a0-intersect.md).
#include "framework/core/float_bits.h"
#include "framework/interface/a0_intersect.h"

#include <cmath>

namespace rtlab {

bool intersectTriangle(const Ray& ray, float tMax, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       TriangleHit* hit) {
    // 1. Translate the vertices so the ray starts at the origin.
    Vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;

    // 2. Permute so the largest direction component is z, then shear the ray onto +z.
    int kz = maxComponentIndex(glm::abs(ray.direction));
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    float dz = ray.direction[kz];
    if (!(dz != 0.0f)) return false;  // zero-length or NaN direction
    float sx = -ray.direction[kx] / dz, sy = -ray.direction[ky] / dz, sz = 1.0f / dz;
    float ax = a[kx] + sx * a[kz], ay = a[ky] + sy * a[kz];
    float bx = b[kx] + sx * b[kz], by = b[ky] + sy * b[kz];
    float cx = c[kx] + sx * c[kz], cy = c[ky] + sy * c[kz];

    // 3. 2D edge functions: exactly antisymmetric between neighbours that share an edge, with
    //    the exact sign, even if the compiler fuses multiply-adds (differenceOfProducts).
    float e0 = differenceOfProducts(bx, cy, by, cx);  // weight of p0
    float e1 = differenceOfProducts(cx, ay, cy, ax);  // weight of p1
    float e2 = differenceOfProducts(ax, by, ay, bx);  // weight of p2
    // Edges count: zero is inside. Mixed signs mean the ray passes outside.
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
    float det = e0 + e1 + e2;
    if (!(det != 0.0f)) return false;  // ray in the triangle's plane, degenerate triangle, NaN

    // 4. Distance, then the acceptance test written so that NaN fails it.
    float az = sz * a[kz], bz = sz * b[kz], cz = sz * c[kz];
    float invDet = 1.0f / det;
    float t = (e0 * az + e1 * bz + e2 * cz) * invDet;
    if (!(t > ray.tMin && t <= tMax) || !std::isfinite(t)) return false;

    hit->t = t;
    hit->b1 = e1 * invDet;
    hit->b2 = e2 * invDet;
    return true;
}

}  // namespace rtlab
