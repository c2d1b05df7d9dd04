// docs/a0-intersect.md, "Watertight triangles", steps 1-5 and the two traps, transcribed
// literally: graded by tests/test_common_mistakes.cpp, it must keep full marks, so the recipe is
// known to work as written. Deliberately not the reference's code.
#include "framework/core/float_bits.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

bool intersectTriangle(const Ray& ray, float tMax, const Vec3& p0, const Vec3& p1, const Vec3& p2, TriangleHit* hit) {
    const Vec3& d = ray.direction;
    // 1. Translate the vertices by -origin.
    Vec3 v[3] = {p0 - ray.origin, p1 - ray.origin, p2 - ray.origin};
    // 2. Permute: the largest component of |d| becomes z; kx, ky the next two, cyclically.
    int kz = maxComponentIndex(glm::abs(d));
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    //    Shear: x' = x - (d[kx]/d[kz]) z, y' = y - (d[ky]/d[kz]) z.
    float x[3], y[3], z[3];
    for (int i = 0; i < 3; ++i) {
        x[i] = v[i][kx] - (d[kx] / d[kz]) * v[i][kz];
        y[i] = v[i][ky] - (d[ky] / d[kz]) * v[i][kz];
        z[i] = v[i][kz] / d[kz];  // z' = z / d[kz], for step 4
    }
    // 3. Edge functions e0 = b'x c'y - b'y c'x and cyclically, with differenceOfProducts (the
    //    FMA trap). Zero counts as inside; mixed signs: miss. (Two-sided: either sign is a hit.)
    float e0 = differenceOfProducts(x[1], y[2], y[1], x[2]);
    float e1 = differenceOfProducts(x[2], y[0], y[2], x[0]);
    float e2 = differenceOfProducts(x[0], y[1], y[0], x[1]);
    bool negative = e0 < 0 || e1 < 0 || e2 < 0, positive = e0 > 0 || e1 > 0 || e2 > 0;
    if (negative && positive) return false;
    // 4. det = e0 + e1 + e2; det == 0: miss. t = (e0 z'0 + e1 z'1 + e2 z'2) / det.
    float det = e0 + e1 + e2;
    if (det == 0) return false;
    float t = (e0 * z[0] + e1 * z[1] + e2 * z[2]) / det;
    // 5. Accept, written so that a NaN t fails.
    if (!(t > ray.tMin && t <= tMax)) return false;
    hit->t = t;
    hit->b1 = e1 / det;
    hit->b2 = e2 / det;
    return true;
}

}  // namespace rtlab
