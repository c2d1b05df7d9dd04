// grader/a6_radiometry/a6_tests.cpp's scoring, fed with raw results as a worker would send
// them: a malformed record fails only its own test; a sampler must be its pinned mapping (another mapping of the
// same distribution loses the mapping's case, samples placed by quota lose every case); an
// estimator's samples must spread as the estimator does (a constant right answer fails).
#include "framework/core/pcg32.h"
#include "framework/interface/a6_radiometry.h"
#include "grader/a6_radiometry/a6_tests.h"
#include "grader/a6_radiometry/radiometry_cases.h"
#include "grader/a6_radiometry/sampler_mappings.h"
#include "framework/render/oracle_rays.h"
#include "grader/engine/grading_report.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <numbers>
#include <set>
#include <string>

using namespace rtlab;
using namespace rtlab::grader;
using worker::Estimator;

namespace {

const TestGroup& groupTitled(const std::vector<TestGroup>& groups, const std::string& title) {
    auto found = std::find_if(groups.begin(), groups.end(), [&](const TestGroup& g) { return g.title == title; });
    REQUIRE(found != groups.end());
    return *found;
}

TestResult scoreOne(const TestGroup& group, const std::vector<std::vector<uint8_t>>& records) {
    SandboxRun run;
    for (const std::vector<uint8_t>& data : records) run.phases.push_back(PhaseOutcome{PhaseStatus::Completed, data, "", 0.0, 0.0});
    std::vector<TestResult> results;
    group.score(run, results);
    REQUIRE(results.size() == 1);
    return results.front();
}

template <typename T>
std::vector<uint8_t> record(const std::vector<T>& values) {
    ByteWriter out;
    out.putVector(values);
    return out.bytes();
}

// A sampler's records: for the given u of phase 0 and the u of every run, what `sample` returns
// (the index of the sample in its run, its u), with the uniform sphere's pdf.
using SamplerModel = std::function<DVec3(const worker::SamplerCall&, uint32_t index, Vec2 u)>;

std::vector<std::vector<uint8_t>> sphereRecords(const TestGroup& group, const SamplerModel& sample) {
    const float pdf = 1.0f / (4.0f * std::numbers::pi_v<float>);
    std::vector<std::vector<uint8_t>> records;
    ByteReader table(group.phases[0].input);
    auto call = table.get<worker::SamplerCall>();
    std::vector<worker::SampleResult> given;
    for (Vec2 u : table.getVector<Vec2>(100)) given.push_back({Vec3(sample(call, 0, u)), pdf});
    records.push_back(record(given));
    for (size_t k = 1; k < group.phases.size(); ++k) {
        auto run = ByteReader(group.phases[k].input).get<worker::SamplerCall>();
        Pcg32 rng(run.seed, 0);
        std::vector<worker::SampleResult> samples;
        for (uint32_t i = 0; i < run.count; ++i) samples.push_back({Vec3(sample(run, i, worker::uniformPair(rng))), pdf});
        records.push_back(record(samples));
    }
    return records;
}

}  // namespace

TEST_CASE("a6 scoring: a malformed or short record fails only its own test, under its name") {
    GradingContext context;
    std::vector<TestGroup> groups = a6Groups(context);
    std::set<std::string> names;
    for (const TestGroup& group : groups) {
        SandboxRun stubs;
        stubs.phases.assign(group.phases.size(), PhaseOutcome{PhaseStatus::NotStarted, {}, "not started", 0.0, 0.0});
        std::vector<TestResult> results;
        group.score(stubs, results);
        for (const TestResult& r : results) names.insert(r.name);
    }
    CHECK(names.size() == groups.size());
    // Three bytes end every record early; a count of 2^63 is longer than any test allows.
    ByteWriter huge;
    huge.put<uint64_t>(uint64_t(1) << 63);
    for (const std::vector<uint8_t>& bad : {std::vector<uint8_t>{1, 2, 3}, huge.bytes()}) {
        for (const TestGroup& group : groups) {
            CAPTURE(group.title);
            TestResult result = scoreOne(group, std::vector<std::vector<uint8_t>>(group.phases.size(), bad));
            CHECK(names.count(result.name) == 1);
            CHECK(result.status == TestStatus::Failed);
            CHECK(result.fraction == 0.0);
            CHECK(result.reason.rfind("sent malformed results: ", 0) == 0);
        }
    }
}

TEST_CASE("a6 scoring: a sampler is judged by its pinned mapping and by a two-sided fit") {
    GradingContext context;
    std::vector<TestGroup> groups = a6Groups(context);
    const TestGroup& sphere = groupTitled(groups, "a6/samplers/uniform-sphere");

    TestResult pinned = scoreOne(sphere, sphereRecords(sphere, [](const worker::SamplerCall& c, uint32_t, Vec2 u) { return pinnedSample(c, u); }));
    CAPTURE(testOutput(pinned));
    CHECK(pinned.status == TestStatus::Passed);

    // z = 2 u.x - 1 instead of 1 - 2 u.x: the same distribution from another mapping.
    TestResult mirrored = scoreOne(
        sphere, sphereRecords(sphere, [](const worker::SamplerCall& c, uint32_t, Vec2 u) { return pinnedSample(c, Vec2(1.0f - u.x, u.y)); }));
    CAPTURE(testOutput(mirrored));
    CHECK(mirrored.fraction == doctest::Approx(0.75));
    CHECK(mirrored.reason.find("the pinned mapping") != std::string::npos);

    // u ignored: sample i at the middle of cell i mod 800 of the grader's 20 x 40 histogram, so
    // every cell gets exactly its 1250.
    TestResult quota = scoreOne(sphere, sphereRecords(sphere, [](const worker::SamplerCall&, uint32_t i, Vec2) {
        int cell = static_cast<int>(i % 800), band = cell / 40, sector = cell % 40;
        double z = -1.0 + (band + 0.5) * 0.1, phi = (sector + 0.5) * 2.0 * std::numbers::pi / 40.0, r = std::sqrt(1.0 - z * z);
        return DVec3(r * std::cos(phi), r * std::sin(phi), z);
    }));
    CAPTURE(testOutput(quota));
    CHECK(quota.fraction == 0.0);
    CHECK(testOutput(quota).find("too good to be random") != std::string::npos);
}

TEST_CASE("a6 scoring: an estimator's samples must spread as the estimator does") {
    GradingContext context;
    std::vector<TestGroup> groups = a6Groups(context);
    const TestGroup& group = groupTitled(groups, "a6/estimators/triangle-area");
    std::vector<EstimatorCase> cases = triangleLightCases(Estimator::TriangleByArea, context.seed);
    // The reference estimator's samples, as the worker draws them: stream k for case k.
    std::vector<std::vector<Vec3>> reference;
    for (size_t k = 0; k < cases.size(); ++k) {
        const EstimatorCase& c = cases[k];
        Oracle oracle(c.scene);
        OracleRays rays(c.scene, oracle, c.call.point.position);
        Pcg32 rng(c.call.seed, k);
        std::vector<Vec3>& samples = reference.emplace_back();
        for (uint32_t i = 0; i < c.call.count; ++i) samples.push_back(estimateTriangleLightByArea(c.call.point, c.call.triangle, worker::uniformPair(rng), rays));
    }
    auto score = [&](const std::function<Vec3(const EstimatorCase&, const Vec3& sample)>& change) {
        ByteWriter out;
        for (size_t k = 0; k < cases.size(); ++k) {
            std::vector<Vec3> changed;
            for (const Vec3& x : reference[k]) changed.push_back(change(cases[k], x));
            out.putVector(changed);
        }
        return scoreOne(group, {out.bytes()});
    };

    TestResult honest = score([](const EstimatorCase&, const Vec3& x) { return x; });
    CAPTURE(testOutput(honest));
    CHECK(honest.status == TestStatus::Passed);

    // The closed form for every u: right wherever the estimator has no spread either (the back
    // of the light, the light behind an occluder), wrong everywhere else.
    TestResult constant = score([](const EstimatorCase& c, const Vec3&) { return Vec3(c.expected); });
    CAPTURE(testOutput(constant));
    CHECK(constant.fraction == doctest::Approx(2.0 / 6.0));
    CHECK(constant.reason.find("no Monte Carlo sample") != std::string::npos);

    // The right mean with half the variance: each sample pulled towards the closed form.
    TestResult narrow = score([](const EstimatorCase& c, const Vec3& x) { return Vec3(DVec3(c.expected) + std::sqrt(0.5) * (DVec3(x) - c.expected)); });
    CAPTURE(testOutput(narrow));
    CHECK(narrow.fraction == doctest::Approx(2.0 / 6.0));
    CHECK(narrow.reason.find("the samples' variance") != std::string::npos);
}
