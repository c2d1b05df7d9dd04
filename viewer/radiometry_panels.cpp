#include "viewer/radiometry_panels.h"

#include "framework/accel/brute_force.h"
#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/oracle/closed_forms.h"
#include "framework/render/accelerator_rays.h"
#include "grader/a6_radiometry/radiometry_cases.h"
#include "grader/a6_radiometry/sampler_histograms.h"
#include "grader/kit/statistics.h"

#include <cmath>

namespace rtlab::viewer {
namespace {

using grader::worker::Estimator;
using grader::worker::Sampler;
using grader::worker::SamplerCall;

// a6's graded runs draw 10^6 samples each (grader/a6_radiometry/a6_tests.cpp): the histogram counts as many.
constexpr uint32_t kSamples = 1000000;

struct SamplerSetup {
    Sampler sampler;
    const char* name;
    const char* domain;
};

// Run 0 of each sampler test, as grader/a6_radiometry/a6_tests.cpp sets it: seed 1000 (sampler + 1), the first
// cone and triangles of its lists.
SamplerCall firstRun(Sampler sampler) {
    SamplerCall c{};
    c.sampler = sampler;
    c.seed = 1000 * (static_cast<uint64_t>(sampler) + 1);
    c.count = kSamples;
    if (sampler == Sampler::UniformCone) c.cosThetaMax = 0.9f;
    if (sampler == Sampler::UniformTriangle) c.p0 = {0, 0, 0}, c.p1 = {1, 0, 0}, c.p2 = {0, 1, 0};
    if (sampler == Sampler::SphericalTriangle) c.p = {0, 0, 0}, c.p0 = {-0.5f, -0.4f, 1}, c.p1 = {0.1f, 0.7f, 0.9f}, c.p2 = {0.6f, -0.3f, 1.2f};
    return c;
}

// The histogram cells and exact counts of one run.
struct Bins {
    std::function<size_t(const Vec3&)> cellOf;
    std::vector<double> expected;
    std::string note;
    int rows = 0, cols = 0;
    double zMin = 0.0;
};

Bins binsOf(const SamplerCall& c) {
    auto directions = [](double zMin, std::function<double(double)> cdf) {
        grader::DirectionBins b{zMin};
        return Bins{[b](const Vec3& v) { return b.cellOf(v); }, b.expected(kSamples, cdf),
                    std::to_string(b.zBands) + " bands of z x " + std::to_string(b.phiSectors) + " sectors of phi, then outside",
                    b.zBands, b.phiSectors, zMin};
    };
    grader::TriangleBins t{DVec3(c.p0), DVec3(c.p1), DVec3(c.p2)};
    std::string lattice = std::to_string(t.k * t.k) + " equal sub-triangles, then off the triangle";
    switch (c.sampler) {
    case Sampler::UniformSphere: return directions(-1.0, [](double z) { return (z + 1.0) / 2.0; });
    case Sampler::UniformHemisphere: return directions(0.0, [](double z) { return z; });
    case Sampler::CosineHemisphere: return directions(0.0, [](double z) { return z * z; });
    case Sampler::UniformCone: {
        double cosMax = c.cosThetaMax;
        return directions(cosMax, [cosMax](double z) { return (z - cosMax) / (1.0 - cosMax); });
    }
    case Sampler::UniformTriangle: {
        std::vector<double> counts(t.cells(), double(kSamples) / (t.k * t.k));
        counts.back() = 0.0;
        return Bins{[t](const Vec3& v) { return t.cellOf(DVec3(v)); }, counts, lattice};
    }
    case Sampler::SphericalTriangle: {
        DVec3 from(c.p);
        double omega = triangleSolidAngleByExcess(from, t.p0, t.p1, t.p2);
        std::vector<double> counts;
        for (const auto& s : t.subTriangles()) counts.push_back(kSamples * triangleSolidAngleByExcess(from, s[0], s[1], s[2]) / omega);
        counts.push_back(0.0);
        return Bins{[t, from](const Vec3& v) { return t.cellOfDirection(from, DVec3(v)); }, counts, lattice + " (by solid angle)"};
    }
    }
    throw Error("viewer: an unknown sampler");
}

}  // namespace

std::vector<SamplerPanel> samplerPanels(const SamplerFunction& sample) {
    const SamplerSetup setups[] = {
        {Sampler::UniformSphere, "sampleUniformSphere", "sphere"},
        {Sampler::UniformHemisphere, "sampleUniformHemisphere", "hemisphere"},
        {Sampler::CosineHemisphere, "sampleCosineHemisphere", "hemisphere"},
        {Sampler::UniformCone, "sampleUniformCone (cos theta_max = 0.9)", "cone"},
        {Sampler::UniformTriangle, "sampleUniformTriangle", "triangle"},
        {Sampler::SphericalTriangle, "sampleSphericalTriangle", "spherical triangle"},
    };
    std::vector<SamplerPanel> panels;
    for (const SamplerSetup& s : setups) {
        SamplerPanel panel;
        panel.name = s.name;
        panel.domain = s.domain;
        SamplerCall call = firstRun(s.sampler);
        panel.triangle = {call.p0, call.p1, call.p2};
        panel.origin = call.p;
        panel.cosThetaMax = call.cosThetaMax;
        try {
            Bins bins = binsOf(call);
            panel.cellsNote = bins.note;
            panel.rows = bins.rows;
            panel.cols = bins.cols;
            panel.zMin = bins.zMin;
            panel.expected = bins.expected;
            panel.observed.assign(bins.expected.size(), 0.0);
            Pcg32 rng(call.seed, 0);
            for (uint32_t i = 0; i < call.count; ++i) {
                float x = rng.uniform();
                Vec2 u(x, rng.uniform());
                Vec3 v = sample(call, u);
                // A sample that is not finite counts as outside, as it fails the grader's test.
                size_t cell = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) ? bins.cellOf(v) : bins.expected.size() - 1;
                panel.observed[std::min(cell, bins.expected.size() - 1)] += 1.0;
                if (i < 4096) {
                    panel.unitSquare.push_back(u);
                    panel.mapped.push_back(v);
                }
            }
            grader::ChiSquareResult chi = grader::chiSquareTest(panel.observed, panel.expected);
            panel.chiSquare = chi.chiSquare;
            panel.pValue = chi.p;
            panel.dof = chi.dof;
        } catch (const NotImplemented& e) {
            panel.error = e.what();
        }
        panels.push_back(std::move(panel));
    }
    return panels;
}

std::vector<EstimatorCurve> estimatorCurves(const EstimatorFunction& estimate) {
    struct Setup {
        Estimator estimator;
        const char* name;
        std::vector<grader::EstimatorCase> (*cases)(Estimator, uint64_t seed);
    };
    const Setup setups[] = {
        {Estimator::TriangleByArea, "estimateTriangleLightByArea", grader::triangleLightCases},
        {Estimator::TriangleBySolidAngle, "estimateTriangleLightBySolidAngle", grader::triangleLightCases},
        {Estimator::SphereByArea, "estimateSphereLightByArea", grader::sphereLightCases},
        {Estimator::SphereBySolidAngle, "estimateSphereLightBySolidAngle", grader::sphereLightCases},
        {Estimator::UniformHemisphere, "estimateByUniformHemisphere", grader::directionCases},
        {Estimator::CosineHemisphere, "estimateByCosineHemisphere", grader::directionCases},
    };
    constexpr int kRuns = 16;
    constexpr uint64_t kCurveSeed = 1;
    std::vector<EstimatorCurve> curves;
    for (const Setup& s : setups) {
        EstimatorCurve curve;
        curve.name = s.name;
        try {
            // The cases are drawn from a grading seed; any seed shows what the curve looks like.
            grader::EstimatorCase c = s.cases(s.estimator, kCurveSeed).front();
            curve.name += " (" + c.id + ")";
            PrimitiveSet primitives(c.scene);
            BruteForce occluders;
            occluders.build(primitives);
            SurfaceHit surface;
            surface.point = c.call.point.position;
            surface.geometricNormal = c.call.point.normal;
            surface.pointError = Vec3(0.0f);
            TraversalStats stats;
            AcceleratorRays rays(c.scene, occluders, surface, sceneReach(c.scene), stats);
            double truth = (c.expected.x + c.expected.y + c.expected.z) / 3.0;
            for (uint32_t n = 16; n <= 16384; n *= 4) {
                double squared = 0.0;
                for (int run = 0; run < kRuns; ++run) {
                    Pcg32 rng(c.call.seed + n, run);
                    double sum = 0.0;
                    for (uint32_t i = 0; i < n; ++i) {
                        float x = rng.uniform();
                        Vec3 v = estimate(c.call, Vec2(x, rng.uniform()), rays);
                        sum += (double(v.x) + v.y + v.z) / 3.0;
                    }
                    double error = (sum / n - truth) / (truth != 0.0 ? truth : 1.0);
                    squared += error * error;
                }
                curve.samples.push_back(n);
                curve.rmsError.push_back(std::sqrt(squared / kRuns));
            }
            curve.slope = grader::logLogSlope(curve.samples, curve.rmsError);
        } catch (const NotImplemented& e) {
            curve.error = e.what();
        }
        curves.push_back(std::move(curve));
    }
    return curves;
}

}  // namespace rtlab::viewer
