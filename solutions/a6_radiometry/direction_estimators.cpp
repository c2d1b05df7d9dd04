// Reference solution: direct light found by shooting directions from the shading point, with
// no knowledge of where the lights are (docs/a6-radiometry.md#estimators-by-direction).
#include "framework/interface/a6_radiometry.h"
#include "reflected_radiance.h"

namespace rtlab {
namespace {

Vec3 estimateAlong(const ShadingPoint& x, const DirectionSample& local, const SceneRays& rays) {
    // Nothing to reflect, or a direction in the horizon: no ray.
    if (x.albedo == Vec3(0.0f) || !(local.direction.z > 0.0f)) return Vec3(0.0f);
    Vec3 w = Frame(x.normal).toWorld(local.direction);
    return reflectedRadiance(x, rays.incomingEmission(w), w, local.pdf);
}

}  // namespace

Vec3 estimateByUniformHemisphere(const ShadingPoint& x, Vec2 u, const SceneRays& rays) {
    return estimateAlong(x, sampleUniformHemisphere(u), rays);
}

// The cosine in the integrand cancels against the density: every sample weighs albedo * L.
Vec3 estimateByCosineHemisphere(const ShadingPoint& x, Vec2 u, const SceneRays& rays) {
    return estimateAlong(x, sampleCosineHemisphere(u), rays);
}

}  // namespace rtlab
