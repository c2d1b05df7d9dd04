// Assignment a6, part 6: direct light by direction.   Guide: docs/a6-radiometry.md#estimators-by-direction
//
// Contract (framework/interface/a6_radiometry.h). ONE sample of the reflected radiance from
// every emitter at once: draw a direction about x.normal (sampleUniformHemisphere or
// sampleCosineHemisphere, turned with Frame(x.normal)), ask rays.incomingEmission(w) for the
// radiance arriving along it, and return (albedo / pi) * L * cos(theta_x) / pdf (0 when
// cos(theta_x) <= 0 or pdf = 0). Point lights are never found this way.
//
// Hints:
//   * With cosine sampling, cos / pdf is pi: every sample is albedo * L.
//   * Skip the ray when the albedo is black.
#include "framework/core/error.h"
#include "framework/interface/a6_radiometry.h"

namespace rtlab {

Vec3 estimateByUniformHemisphere(const ShadingPoint& x, Vec2 u, const SceneRays& rays) {
    (void)x, (void)u, (void)rays;
    throw NotImplemented("a6 estimateByUniformHemisphere (assignments/a6_radiometry/direction_estimators.cpp)");
}

Vec3 estimateByCosineHemisphere(const ShadingPoint& x, Vec2 u, const SceneRays& rays) {
    (void)x, (void)u, (void)rays;
    throw NotImplemented("a6 estimateByCosineHemisphere (assignments/a6_radiometry/direction_estimators.cpp)");
}

}  // namespace rtlab
