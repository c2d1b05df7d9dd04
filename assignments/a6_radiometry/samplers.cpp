// Assignment a6, part 3: samplers and their pdfs.   Guide: docs/a6-radiometry.md#samplers
//
// Contract (framework/interface/a6_radiometry.h). u = (u.x, u.y) uniform in [0, 1)^2;
// directions about +z with z = cos(theta), phi = 2 pi u.y; pdf of what is returned:
//   sampleUniformSphere      z = 1 - 2 u.x                      pdf 1 / (4 pi)
//   sampleUniformHemisphere  z = u.x                            pdf 1 / (2 pi)
//   sampleCosineHemisphere   r = sqrt(u.x) on the disk, z = sqrt(1 - r^2)   pdf z / pi
//   sampleUniformCone        z = 1 - u.x (1 - cosThetaMax)      pdf 1 / (2 pi (1 - cosThetaMax))
//   sampleUniformTriangle    s = sqrt(u.x): b0 = 1 - s, b1 = u.y s, b2 = 1 - b0 - b1,
//                            point b0 p0 + b1 p1 + b2 p2        pdf 1 / area
//   areaToSolidAnglePdf      pdfArea d^2 / |cos(theta_light)|, infinite when the cosine is 0
//
// Hints:
//   * A direction at height z: (r cos phi, r sin phi, z) with r = sqrt(max(0, 1 - z^2)).
//   * theta = pi u.x is NOT uniform on the sphere: it crowds the poles. Uniform in z is.
//   * The pdf is the one of the direction you return: a cosine sampler's is cos(theta) / pi,
//     not 1 / (2 pi).
//   * The triangle's area is half the length of (p1 - p0) x (p2 - p0).
#include "framework/core/error.h"
#include "framework/interface/a6_radiometry.h"

namespace rtlab {

DirectionSample sampleUniformSphere(Vec2) { throw NotImplemented("a6 sampleUniformSphere (assignments/a6_radiometry/samplers.cpp)"); }
DirectionSample sampleUniformHemisphere(Vec2) { throw NotImplemented("a6 sampleUniformHemisphere (assignments/a6_radiometry/samplers.cpp)"); }
DirectionSample sampleCosineHemisphere(Vec2) { throw NotImplemented("a6 sampleCosineHemisphere (assignments/a6_radiometry/samplers.cpp)"); }
DirectionSample sampleUniformCone(Vec2, float) { throw NotImplemented("a6 sampleUniformCone (assignments/a6_radiometry/samplers.cpp)"); }
PointSample sampleUniformTriangle(const Vec3&, const Vec3&, const Vec3&, Vec2) { throw NotImplemented("a6 sampleUniformTriangle (assignments/a6_radiometry/samplers.cpp)"); }
float areaToSolidAnglePdf(float, float, float) { throw NotImplemented("a6 areaToSolidAnglePdf (assignments/a6_radiometry/samplers.cpp)"); }

}  // namespace rtlab
