// Assignment a0, part 2: watertight ray-triangle.   Guide: docs/a0-intersect.md#watertight-triangles
//
// Contract (framework/interface/a0_intersect.h):
//   Two-sided. Return true when the ray hits the triangle (p0, p1, p2) at a distance t with
//   ray.tMin < t <= tMax, and fill *hit with t and the barycentric weights b1 (of p1) and
//   b2 (of p2). Rays through an edge or vertex hit; NaN anywhere never hits.
//
// Hints (the algorithm of Woop, Benthin and Wald 2013):
//   1. Translate the vertices by -ray.origin.
//   2. kz = axis of the largest |direction| component; kx, ky the next two. Shear the
//      vertices so the ray points along +kz.
//   3. Edge functions e0, e1, e2 with differenceOfProducts (framework/core/float_bits.h):
//      a plain a*b - c*d stops being watertight when the compiler uses FMA.
//   4. Reject mixed signs and det = e0 + e1 + e2 == 0; then t = (e0*z0 + e1*z1 + e2*z2) / det.
//   5. Accept with `if (!(t > ray.tMin && t <= tMax)) return false;`, which NaN fails.
#include "framework/core/error.h"
#include "framework/core/float_bits.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

bool intersectTriangle(const Ray& ray, float tMax, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       TriangleHit* hit) {
    (void)ray, (void)tMax, (void)p0, (void)p1, (void)p2, (void)hit;
    throw NotImplemented("a0 intersectTriangle (assignments/a0_intersect/ray_triangle.cpp)");
}

}  // namespace rtlab
