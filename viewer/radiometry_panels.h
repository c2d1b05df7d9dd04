// a6 in the viewer (docs/viewer.md#a6-samplers-and-estimators): each sampler's points in the unit
// square and on its domain, the histogram of a million of them against the exact counts with the
// chi-square p-value the grader computes for its first run (the same seed, bins and test:
// grader/a6_radiometry/sampler_histograms.h, grader/kit/statistics.h), and each estimator's RMS error against its
// closed form as the sample count grows. Student code comes in as functions, so this file names
// no assignment function (the viewer library links into rtlab-grader too).
#pragma once

#include "framework/interface/radiometry.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"
#include "viewer/case_view.h"

#include <functional>

namespace rtlab::viewer {

// What the linked sampler returns for call and u: a direction, or a point of the triangle.
using SamplerFunction = std::function<Vec3(const grader::worker::SamplerCall& call, Vec2 u)>;
// One sample of the linked estimator named by call.estimator.
using EstimatorFunction = std::function<Vec3(const grader::worker::EstimatorCall& call, Vec2 u, const SceneRays& rays)>;

// Every sampler a6 grades, drawn; one that throws gets its message instead.
std::vector<SamplerPanel> samplerPanels(const SamplerFunction& sample);
// Every estimator with a random sample, on the first of its graded cases.
std::vector<EstimatorCurve> estimatorCurves(const EstimatorFunction& estimate);

}  // namespace rtlab::viewer
