// grader/a6_radiometry/radiometry_cases: the estimator cases drawn from the grading seed. The same seed draws
// the same cases and another seed others; every closed form and every spread the grader
// integrates is what the reference estimators (solutions/a6_radiometry) actually produce, run
// here through the same exact oracle as in the worker.
#include "framework/core/pcg32.h"
#include "framework/interface/a6_radiometry.h"
#include "grader/a6_radiometry/radiometry_cases.h"
#include "grader/a6_radiometry/wire/sample_calls.h"
#include "grader/kit/statistics.h"
#include "framework/render/oracle_rays.h"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace rtlab;
using namespace rtlab::grader;
using worker::Estimator;

namespace {

std::vector<EstimatorCase> everyCase(uint64_t seed) {
    std::vector<EstimatorCase> all = pointLightCases(seed);
    for (const auto& family : {triangleLightCases(Estimator::TriangleByArea, seed), triangleLightCases(Estimator::TriangleBySolidAngle, seed),
                               sphereLightCases(Estimator::SphereByArea, seed), sphereLightCases(Estimator::SphereBySolidAngle, seed),
                               directionCases(Estimator::UniformHemisphere, seed), directionCases(Estimator::CosineHemisphere, seed)})
        all.insert(all.end(), family.begin(), family.end());
    return all;
}

}  // namespace

TEST_CASE("a6 cases: drawn from the grading seed") {
    std::vector<EstimatorCase> first = everyCase(20260101), again = everyCase(20260101), other = everyCase(7);
    REQUIRE(first.size() == again.size());
    REQUIRE(first.size() == other.size());
    size_t moved = 0;
    for (size_t i = 0; i < first.size(); ++i) {
        CAPTURE(first[i].id);
        CHECK(first[i].id == other[i].id);  // the same kinds of case, ...
        CHECK(first[i].inputs == again[i].inputs);
        CHECK(first[i].call.seed == again[i].call.seed);
        if (first[i].inputs != other[i].inputs) ++moved;  // ... in other places
    }
    CHECK(moved == first.size());
}

TEST_CASE("a6 cases: the closed forms and spreads are those of the reference estimators") {
    // 2^18 samples a case: means within 5 standard errors, variances within 5 standard errors
    // plus the 0.5 % the grader allows its quadrature.
    const uint32_t samples = 1u << 18;
    for (uint64_t seed : {uint64_t(20260101), uint64_t(3)}) {
        for (const EstimatorCase& c : everyCase(seed)) {
            CAPTURE(seed);
            CAPTURE(c.id);
            CAPTURE(c.inputs);
            Oracle oracle(c.scene);
            OracleRays rays(c.scene, oracle, c.call.point.position);
            Pcg32 rng(c.call.seed, 0);
            std::array<MeanEstimate, 3> m;
            uint32_t count = c.call.estimator == Estimator::PointLight ? 1 : samples;
            for (uint32_t i = 0; i < count; ++i) {
                Vec3 x = worker::estimateSample(c.call, worker::uniformPair(rng), rays);
                for (int ch = 0; ch < 3; ++ch) m[ch].add(x[ch]);
            }
            for (int ch = 0; ch < 3; ++ch) {
                CAPTURE(ch);
                double variance = c.spread.variance[ch];
                if (variance == 0.0) {
                    CHECK(m[ch].variance() == 0.0);
                    CHECK(m[ch].mean == doctest::Approx(c.expected[ch]).epsilon(1e-5).scale(1e-7));
                    continue;
                }
                CHECK(std::abs(m[ch].mean - c.expected[ch]) <= 5.0 * m[ch].standardError());
                double error = varianceStandardError(m[ch].count, variance, c.spread.fourthMoment[ch]);
                CHECK(std::abs(m[ch].variance() - variance) <= 5.0 * error + 0.005 * variance);
            }
        }
    }
}
