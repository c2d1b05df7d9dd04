#include "grader/kit/accelerator_checks.h"

#include "framework/oracle/oracle.h"
#include "grader/wire/scene_codec.h"

#include <algorithm>
#include <cstdio>
#include <time.h>

namespace rtlab::grader {
namespace {

std::string formatMilliseconds(double seconds) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g ms", 1e3 * seconds);
    return buffer;
}

// What a brute force costs per ray on this scene, on this machine, now: the oracle's closest
// hit over every primitive, timed on the grader's own thread.
double bruteForceSecondsPerRay(const PreparedScene& scene) {
    Oracle oracle(scene.test.scene);
    size_t count = std::min<size_t>(kTimedOracleRays, scene.rays.rays.size());
    timespec start{}, end{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &start);
    for (size_t i = 0; i < count; ++i) oracle.closestHit(OracleRay::from(scene.rays.rays[i]));
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &end);
    double elapsed = double(end.tv_sec - start.tv_sec) + 1e-9 * double(end.tv_nsec - start.tv_nsec);
    return count ? elapsed / double(count) : 0.0;
}

}  // namespace

std::string formatNumber(double v) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    return buffer;
}

std::optional<std::vector<worker::RawQuery>> readQueries(const PhaseOutcome& outcome, size_t count, TestResult& result) {
    if (failedPhaseResult(outcome, result)) return std::nullopt;
    try {
        ByteReader in(outcome.data);
        auto answers = in.getVector<worker::RawQuery>(count);
        if (answers.size() != count) throw WireError("wrong number of answers");
        return answers;
    } catch (const WireError& e) {
        result.status = TestStatus::Failed;
        result.reason = std::string("sent malformed results: ") + e.what();
        return std::nullopt;
    }
}

double meanWork(const std::vector<worker::RawQuery>& answers) {
    double sum = 0.0;
    for (const worker::RawQuery& a : answers) sum += double(a.nodeVisits) + a.primitiveTests;
    return answers.empty() ? 0.0 : sum / double(answers.size());
}

size_t judgeClosestHits(PreparedScene& scene, const std::vector<worker::RawQuery>& answers, TestResult& result, const std::string& tag,
                        std::vector<WrongRay>* wrongRays) {
    size_t wrong = 0;
    std::string first;
    for (size_t i = 0; i < answers.size(); ++i) {
        const Ray& ray = scene.rays.rays[i];
        std::string problem = scene.judge->judgeClosest(i, ray, scene.rays.mustHit[i], HitAnswer{answers[i].prim, answers[i].t});
        if (problem.empty()) continue;
        std::string line = tag + "ray " + std::to_string(i) + " (" + rayKindName(scene.rays.kinds[i]) + ") " + describeRay(ray) + ": " + problem;
        if (wrongRays && wrongRays->size() < kViewerCasesPerTest) wrongRays->push_back({i, problem});
        if (wrong++ < 5) result.details.push_back(line);
        if (first.empty()) first = line;
    }
    if (wrong == 0) markPassed(result, tag + std::to_string(answers.size()) + " rays, all right");
    else markFailed(result, std::to_string(wrong) + " of " + std::to_string(answers.size()) + " rays wrong; first: " + first);
    return wrong;
}

size_t judgeOcclusion(PreparedScene& scene, const std::vector<worker::RawQuery>& answers, TestResult& result, const std::string& tag,
                      std::vector<WrongRay>* wrongRays) {
    size_t wrong = 0;
    std::string first;
    for (size_t i = 0; i < answers.size(); ++i) {
        const Ray& ray = scene.anyHitRays[i];
        std::string problem = scene.anyHitJudge->judgeOccluded(i, ray, false, answers[i].prim != 0);
        if (problem.empty()) continue;
        std::string line = tag + "ray " + std::to_string(i) + " (" + rayKindName(scene.rays.kinds[i]) + ") " + describeRay(ray) + ": " + problem;
        if (wrongRays && wrongRays->size() < kViewerCasesPerTest) wrongRays->push_back({i, problem});
        if (wrong++ < 5) result.details.push_back(line);
        if (first.empty()) first = line;
    }
    if (wrong == 0) markPassed(result, tag + std::to_string(answers.size()) + " any-hit rays, all right");
    else markFailed(result, std::to_string(wrong) + " of " + std::to_string(answers.size()) + " any-hit rays wrong; first: " + first);
    return wrong;
}

// The efficiency verdict (docs/grading.md#what-is-tested): the CPU time the kernel counted for
// the worker, against a brute force over the same scene timed by the grader in the same run.
// The framework's counters are shown too, but live in the worker, so they are feedback, not
// evidence.
EfficiencyVerdict measureEfficiency(const PreparedScene& scene, double cpuSeconds, size_t phases, size_t queries, const std::string& what) {
    double brute = double(queries) * scene.bruteForceSecondsPerRay;
    double allowed = kBruteForceShare * brute + kPhaseSlackSeconds * double(phases);
    return {cpuSeconds <= allowed, what + " CPU time " + formatMilliseconds(cpuSeconds) + " for " + std::to_string(queries) +
                                       " queries (counted by the kernel); a brute force over the " + std::to_string(scene.primBounds.size()) +
                                       " primitives takes about " + formatMilliseconds(brute) + " here; allowed " + formatMilliseconds(allowed)};
}

std::shared_ptr<PreparedScene> prepareScene(TestScene test, uint64_t seed) {
    auto scene = std::make_shared<PreparedScene>();
    scene->test = std::move(test);
    const Scene& s = scene->test.scene;
    for (uint32_t i = 0; i < s.primitiveCount(); ++i) scene->primBounds.push_back(s.primitiveBounds(i));
    scene->rays = makeRaySet(scene->test, kRaysPerScene, seed);
    scene->anyHitRays = withRandomTMax(scene->rays.rays, s, seed);
    scene->sha256 = sceneGeometrySha256(s);
    scene->judge = std::make_unique<HitJudge>(s, scene->rays.rays.size());
    scene->anyHitJudge = std::make_unique<HitJudge>(s, scene->anyHitRays.size());
    return scene;
}

const PreparedScenes& hitSetScenes(GradingContext& context) {
    if (!context.scenes) {
        context.scenes = std::make_shared<PreparedScenes>();
        for (TestScene& test : grader::hitSetScenes(context.modelsDir))
            context.scenes->list.push_back(prepareScene(std::move(test), context.seed));
        // Efficiency is judged where a brute force is far slower than any tree: the largest scene.
        auto largest = std::max_element(context.scenes->list.begin(), context.scenes->list.end(),
                                        [](const auto& a, const auto& b) { return a->primBounds.size() < b->primBounds.size(); });
        if (largest != context.scenes->list.end()) (*largest)->bruteForceSecondsPerRay = bruteForceSecondsPerRay(**largest);
    }
    return *context.scenes;
}

}  // namespace rtlab::grader
