// Assignment a6, part 2: solid angles.              Guide: docs/a6-radiometry.md#solid-angle
//
// Contract (framework/interface/a6_radiometry.h), in double, steradians, 1e-9 relative:
//   solidAngleOfCone(a)          2 pi (1 - cos a), also for a as small as 1e-8
//   solidAngleOfSphere(r, d)     the cone of sin a = r / d; 4 pi when d <= r
//   solidAngleOfTriangle(p, a, b, c)   Van Oosterom-Strackee, unsigned, up to 2 pi
//   solidAngleOfRectangle(p, corner, u, v)   corner, corner + u, corner + u + v, corner + v
//   integrateOverSphere(f, n, m)  the midpoint rule over n x m cells of (theta, phi):
//       sum of f(theta_i, phi_j) sin(theta_i) (pi / n) (2 pi / m),
//       theta_i = (i + 0.5) pi / n, phi_j = (j + 0.5) 2 pi / m
//
// Hints:
//   * 1 - cos(a) for a = 1e-8 is 0 in double. 1 - cos a = 2 sin^2(a / 2) has no difference.
//   * tan(Omega / 2) = N / D: 2 * atan(N / D) is wrong whenever D < 0 (Omega > pi). Use atan2.
//   * Split the rectangle into two triangles along a diagonal.
#include "framework/core/error.h"
#include "framework/interface/a6_radiometry.h"

namespace rtlab {

double solidAngleOfCone(double) { throw NotImplemented("a6 solidAngleOfCone (assignments/a6_radiometry/solid_angle.cpp)"); }
double solidAngleOfSphere(double, double) { throw NotImplemented("a6 solidAngleOfSphere (assignments/a6_radiometry/solid_angle.cpp)"); }
double solidAngleOfTriangle(const DVec3&, const DVec3&, const DVec3&, const DVec3&) { throw NotImplemented("a6 solidAngleOfTriangle (assignments/a6_radiometry/solid_angle.cpp)"); }
double solidAngleOfRectangle(const DVec3&, const DVec3&, const DVec3&, const DVec3&) { throw NotImplemented("a6 solidAngleOfRectangle (assignments/a6_radiometry/solid_angle.cpp)"); }
double integrateOverSphere(const std::function<double(double, double)>&, int, int) { throw NotImplemented("a6 integrateOverSphere (assignments/a6_radiometry/solid_angle.cpp)"); }

}  // namespace rtlab
