// Reference solution: the one step every estimator of a6 ends with.
#pragma once

#include "framework/interface/radiometry.h"

#include <glm/glm.hpp>
#include <numbers>

namespace rtlab {

// One sample of the reflected radiance: Lambert's BRDF albedo / pi, times the radiance arriving
// along the unit direction w, times cos(theta_x), divided by the density w was drawn with.
// Light from below the horizon and samples of density 0 count nothing.
inline Vec3 reflectedRadiance(const ShadingPoint& x, const Vec3& radiance, const Vec3& w, float pdf) {
    float cosX = glm::dot(x.normal, w);
    if (!(cosX > 0.0f) || !(pdf > 0.0f)) return Vec3(0.0f);
    return x.albedo * std::numbers::inv_pi_v<float> * radiance * (cosX / pdf);
}

}  // namespace rtlab
