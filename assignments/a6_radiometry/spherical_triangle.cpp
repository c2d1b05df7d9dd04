// Assignment a6, part 4: sampling a spherical triangle.   Guide: docs/a6-radiometry.md#spherical-triangles
//
// Contract (framework/interface/a6_radiometry.h): a direction from p, uniform over the solid
// angle Omega of the triangle p0, p1, p2; pdf 1 / Omega (0 for a degenerate triangle).
// Arvo's mapping (SIGGRAPH 1995), with A, B, C the unit vectors from p to p0, p1, p2 and
// alpha, beta, gamma the triangle's angles at A, B, C:
//   Omega = alpha + beta + gamma - pi
//   area' = u.x Omega;  s = sin(area' - alpha);  t = cos(area' - alpha)
//   uu = t - cos(alpha);  v = s + sin(alpha) (A . B)
//   q  = ((v t - uu s) cos(alpha) - v) / ((v s + uu t) sin(alpha))        (cos of arc A..C')
//   C' = q A + sqrt(1 - q^2) normalize(C - (C . A) A)
//   z  = 1 - u.y (1 - C' . B)
//   direction = z B + sqrt(1 - z^2) normalize(C' - (C' . B) B)
//
// Hints:
//   * The angle at A is the angle between the planes of its two edges: between the normals
//     A x B and A x C. atan2(|a x b|, a . b) is accurate where acos(a . b) is not.
//   * Work in double (DVec3): q divides differences of nearly equal numbers.
//   * Clamp q to [-1, 1] before the square root.
#include "framework/core/error.h"
#include "framework/interface/a6_radiometry.h"

namespace rtlab {

DirectionSample sampleSphericalTriangle(const Vec3& p, const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u) {
    (void)p, (void)p0, (void)p1, (void)p2, (void)u;
    throw NotImplemented("a6 sampleSphericalTriangle (assignments/a6_radiometry/spherical_triangle.cpp)");
}

}  // namespace rtlab
