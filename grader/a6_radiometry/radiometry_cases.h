// The shading points and lights a6's estimators are graded on (docs/a6-radiometry.md#how-the-grader-checks-it):
// each case with its answer in closed form and what the common mistakes would make of it, so a
// failing mean can be named ("it matches the radiance without the 1/pi of the BRDF").
#pragma once

#include "framework/scene/scene.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct Mistake {
    std::string what;  // "the 1/pi of Lambert's BRDF is missing"
    DVec3 value;       // the mean an estimator with that mistake has, per channel
};

struct EstimatorCase {
    std::string id;            // "T1 a triangle facing the point"
    Scene scene;               // the lights as emissive geometry, and occluders
    worker::EstimatorCall call;
    DVec3 expected;            // the exact mean, per channel
    std::vector<Mistake> mistakes;
};

// Samples per case: enough for a standard error below 1 % of every non-zero answer.
inline constexpr uint32_t kLightSamplesPerCase = 1u << 18;
inline constexpr uint32_t kDirectionSamplesPerCase = 1u << 20;

std::vector<EstimatorCase> pointLightCases();
// Estimator TriangleByArea or TriangleBySolidAngle.
std::vector<EstimatorCase> triangleLightCases(worker::Estimator estimator);
// Estimator SphereByArea or SphereBySolidAngle.
std::vector<EstimatorCase> sphereLightCases(worker::Estimator estimator);
// Estimator UniformHemisphere or CosineHemisphere: a triangle and a sphere light together, seen
// from a point facing up, a tilted one and one on a wall.
std::vector<EstimatorCase> directionCases(worker::Estimator estimator);

}  // namespace rtlab::grader
