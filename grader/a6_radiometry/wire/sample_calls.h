// One sample of the sampler a SamplerCall names, or of the estimator an EstimatorCall names,
// through the implementation linked in: the worker grades the student's with them, rtlab view
// draws the linked one's and the tests run the reference's.
#pragma once

#include "framework/interface/a6_radiometry.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"
#include "grader/wire/wire_format.h"

namespace rtlab::grader::worker {

inline SampleResult sampleOnce(const SamplerCall& c, Vec2 u) {
    switch (c.sampler) {
        case Sampler::UniformSphere: { auto s = sampleUniformSphere(u); return {s.direction, s.pdf}; }
        case Sampler::UniformHemisphere: { auto s = sampleUniformHemisphere(u); return {s.direction, s.pdf}; }
        case Sampler::CosineHemisphere: { auto s = sampleCosineHemisphere(u); return {s.direction, s.pdf}; }
        case Sampler::UniformCone: { auto s = sampleUniformCone(u, c.cosThetaMax); return {s.direction, s.pdf}; }
        case Sampler::UniformTriangle: { auto s = sampleUniformTriangle(c.p0, c.p1, c.p2, u); return {s.point, s.pdf}; }
        case Sampler::SphericalTriangle: {
            auto s = sampleSphericalTriangle(c.p, c.p0, c.p1, c.p2, u);
            return {s.direction, s.pdf};
        }
    }
    throw WireError("an unknown sampler");
}

inline Vec3 estimateSample(const EstimatorCall& c, Vec2 u, const SceneRays& rays) {
    switch (c.estimator) {
        case Estimator::PointLight: return estimatePointLight(c.point, c.pointLight, rays);
        case Estimator::TriangleByArea: return estimateTriangleLightByArea(c.point, c.triangle, u, rays);
        case Estimator::TriangleBySolidAngle: return estimateTriangleLightBySolidAngle(c.point, c.triangle, u, rays);
        case Estimator::SphereByArea: return estimateSphereLightByArea(c.point, c.sphere, u, rays);
        case Estimator::SphereBySolidAngle: return estimateSphereLightBySolidAngle(c.point, c.sphere, u, rays);
        case Estimator::UniformHemisphere: return estimateByUniformHemisphere(c.point, u, rays);
        case Estimator::CosineHemisphere: return estimateByCosineHemisphere(c.point, u, rays);
    }
    throw WireError("an unknown estimator");
}

}  // namespace rtlab::grader::worker
