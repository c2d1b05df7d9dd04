// The checks every acceleration structure gets, whoever built it (docs/grading.md): hit sets of
// closest-hit and any-hit traversals judged ray by ray against the exact oracle, and the
// efficiency verdict from the CPU time the kernel counted against a brute force the grader times
// itself. The BVH tests (bvh_tests.cpp) and the grid tests (a3_tests.cpp) are built on them.
#pragma once

#include "grader/kit/hit_judge.h"
#include "grader/kit/ray_sets.h"
#include "grader/engine/test_group.h"
#include "grader/kit/test_scenes.h"
#include "grader/wire/task_inputs.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::grader {

// A scene with everything the parent prepares once: primitive set, rays, the oracle's judge.
struct PreparedScene {
    TestScene test;
    std::vector<Bounds3f> primBounds;
    RaySet rays;
    std::vector<Ray> anyHitRays;
    std::string sha256;
    std::unique_ptr<HitJudge> judge;       // closest-hit rays
    std::unique_ptr<HitJudge> anyHitJudge;
    // Set on the scene whose traversal time is judged (the largest): what the oracle's brute
    // force took per ray when the grader timed it.
    double bruteForceSecondsPerRay = 0.0;
};

struct PreparedScenes {
    std::vector<std::shared_ptr<PreparedScene>> list;
};

// Efficiency bound (docs/grading.md#what-is-tested): the traversals' CPU time at most this share
// of a brute force's over the same queries, plus kPhaseSlackSeconds per query phase. A correct
// traversal takes a few percent of a brute force on the largest test scene; a brute force
// through the framework's intersect takes about twice the oracle's time.
inline constexpr double kBruteForceShare = 0.25;
inline constexpr double kPhaseSlackSeconds = 0.005;
inline constexpr size_t kTimedOracleRays = 200;
inline constexpr int kRaysPerScene = 1000;

// A scene with its rays and judges (no timing).
std::shared_ptr<PreparedScene> prepareScene(TestScene test, uint64_t seed);
// The hit-set scenes of test_scenes.h, prepared once per grading run and shared by every
// structure; the largest carries the brute force's time per ray.
const PreparedScenes& hitSetScenes(GradingContext& context);

std::string formatNumber(double v);

// The answers of a query phase, or nullopt with result failed (or not started) and why.
std::optional<std::vector<worker::RawQuery>> readQueries(const PhaseOutcome& outcome, size_t count, TestResult& result);
// Mean framework-counted work per query (box tests and cell steps plus primitive tests).
double meanWork(const std::vector<worker::RawQuery>& answers);

// A ray judged wrong: its index in the set and what was wrong, for the report's viewer links.
struct WrongRay {
    size_t index;
    std::string problem;
};

// Judge closest-hit or any-hit answers ray by ray; fill result; return the wrong rays' count.
// With `wrongRays`, the first kViewerCasesPerTest wrong rays are listed there.
size_t judgeClosestHits(PreparedScene& scene, const std::vector<worker::RawQuery>& answers, TestResult& result,
                        const std::string& tag, std::vector<WrongRay>* wrongRays = nullptr);
size_t judgeOcclusion(PreparedScene& scene, const std::vector<worker::RawQuery>& answers, TestResult& result,
                      const std::string& tag, std::vector<WrongRay>* wrongRays = nullptr);

// The efficiency verdict on CPU time the kernel counted for `phases` worker phases that answered
// `queries` queries: within kBruteForceShare of the scene's timed brute force over as many
// queries, plus kPhaseSlackSeconds a phase. `what` names the work timed in the line.
struct EfficiencyVerdict {
    bool fast = false;
    std::string line;
};
EfficiencyVerdict measureEfficiency(const PreparedScene& scene, double cpuSeconds, size_t phases, size_t queries, const std::string& what);

}  // namespace rtlab::grader
