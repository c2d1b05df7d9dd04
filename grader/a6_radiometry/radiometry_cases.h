// The shading points and lights a6's estimators are graded on (docs/a6-radiometry.md#how-the-grader-checks-it),
// drawn from the grading seed within documented ranges so that no estimator can recognise them:
// each case with its answer in closed form, the spread one sample of the estimator has about
// it, and what the common mistakes would make of it, so a failing mean can be named ("it
// matches the radiance without the 1/pi of the BRDF").
#pragma once

#include "framework/scene/scene.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::grader {

struct Mistake {
    std::string what;  // "the 1/pi of Lambert's BRDF is missing"
    DVec3 value;       // the mean an estimator with that mistake has, per channel
};

// How one sample of a correct estimator spreads about its mean, per channel: its variance and
// its fourth central moment (which says how precisely a sample's variance estimates the
// variance). Integrated over the light by the grader, without student code; zero for a
// deterministic estimate (a point light, a light nothing of which reaches the point).
struct Spread {
    DVec3 variance{0.0};
    DVec3 fourthMoment{0.0};
};

struct EstimatorCase {
    std::string id;      // "T1 a triangle facing the point"
    std::string inputs;  // the drawn shading point and light, for the report
    Scene scene;         // the lights as emissive geometry, and occluders
    worker::EstimatorCall call;
    DVec3 expected{0.0};  // the exact mean, per channel
    Spread spread;
    std::vector<Mistake> mistakes;
};

// Samples per case: enough for a standard error below 1 % of every non-zero answer.
inline constexpr uint32_t kLightSamplesPerCase = 1u << 18;
inline constexpr uint32_t kDirectionSamplesPerCase = 1u << 20;

// Every family draws its cases from `seed`, the grading seed: the same seed gives the same
// cases, another seed other ones.
std::vector<EstimatorCase> pointLightCases(uint64_t seed);
// Estimator TriangleByArea or TriangleBySolidAngle.
std::vector<EstimatorCase> triangleLightCases(worker::Estimator estimator, uint64_t seed);
// Estimator SphereByArea or SphereBySolidAngle.
std::vector<EstimatorCase> sphereLightCases(worker::Estimator estimator, uint64_t seed);
// Estimator UniformHemisphere or CosineHemisphere: a triangle and a sphere light together, seen
// from a point facing up, a tilted one and one on a wall.
std::vector<EstimatorCase> directionCases(worker::Estimator estimator, uint64_t seed);

}  // namespace rtlab::grader
