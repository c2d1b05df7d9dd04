// Assignment a6, part 5: direct light from one light.     Guide: docs/a6-radiometry.md#estimators
//
// Contract (framework/interface/a6_radiometry.h). Each function returns ONE sample of
//   L = integral over the light of  (albedo / pi) L_e cos(theta_x) dOmega
// (the point light: exactly albedo/pi I cos(theta_x) / d^2). With w the unit direction from
// x.position to the light point y and pdf the density of w per steradian, one sample is
//   (albedo / pi) * L_e * cos(theta_x) / pdf       if cos(theta_x) = x.normal . w > 0,
//                                                  y emits towards x and rays.visible(y),
//   0                                              otherwise.
//   ...ByArea:       y from sampleUniformTriangle / centre + radius * sampleUniformSphere(u);
//                    pdf = areaToSolidAnglePdf(pdfArea, d^2, cos(theta_light))
//   ...BySolidAngle: w from sampleSphericalTriangle / sampleUniformCone (about the direction
//                    to the centre, sin(theta_max) = radius / d; turn it with Frame);
//                    y = where w meets the triangle's plane / first meets the sphere.
// A triangle emits on the side (p1 - p0) x (p2 - p0) points to, or on both when twoSided; a
// sphere emits outwards, and nothing reaches a point inside it.
//
// Hints:
//   * Check cos(theta_x), the emitting side and a non-zero value before the shadow ray: rays
//     are the expensive part.
//   * The far half of a sphere faces away from x: its cos(theta_light) is negative.
//   * Along w at angle theta from the centre, the sphere is first met at
//     t = d cos(theta) - sqrt(r^2 - d^2 sin^2(theta)).
#include "framework/core/error.h"
#include "framework/interface/a6_radiometry.h"

namespace rtlab {

Vec3 estimatePointLight(const ShadingPoint&, const PointEmitter&, const SceneRays&) { throw NotImplemented("a6 estimatePointLight (assignments/a6_radiometry/light_estimators.cpp)"); }
Vec3 estimateTriangleLightByArea(const ShadingPoint&, const TriangleEmitter&, Vec2, const SceneRays&) {
    throw NotImplemented("a6 estimateTriangleLightByArea (assignments/a6_radiometry/light_estimators.cpp)");
}
Vec3 estimateTriangleLightBySolidAngle(const ShadingPoint&, const TriangleEmitter&, Vec2, const SceneRays&) {
    throw NotImplemented("a6 estimateTriangleLightBySolidAngle (assignments/a6_radiometry/light_estimators.cpp)");
}
Vec3 estimateSphereLightByArea(const ShadingPoint&, const SphereEmitter&, Vec2, const SceneRays&) {
    throw NotImplemented("a6 estimateSphereLightByArea (assignments/a6_radiometry/light_estimators.cpp)");
}
Vec3 estimateSphereLightBySolidAngle(const ShadingPoint&, const SphereEmitter&, Vec2, const SceneRays&) {
    throw NotImplemented("a6 estimateSphereLightBySolidAngle (assignments/a6_radiometry/light_estimators.cpp)");
}

}  // namespace rtlab
