// The tests every BVH build configuration gets (docs/grading.md): structure invariants, the
// SAH cost against the reference, hit sets of the ordered, recursive and any-hit traversals
// against the oracle, traversal work against the reference, and the degenerate inputs of the
// stress catalogue (BVH-01, -02, -03, -07, -08, TRI-12, TRI-13).
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/bvh.h"
#include "grader/hit_judge.h"
#include "grader/ray_sets.h"
#include "grader/test_group.h"
#include "grader/test_scenes.h"

#include <memory>
#include <string>
#include <vector>

namespace rtlab::grader {

struct BvhConfig {
    std::string assignment;  // "a1"
    std::string label;       // "median", "buckets-12": names the tests and the reference entries
    BvhOptions options;
    std::string buildStub;   // named in verdicts: "a1 buildBvh + a1 splitMedian"
    bool exactSah = false;   // median, middle, equal counts: the reference tree exactly
    bool recursive = false;  // also grade intersectBvhRecursive
};

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

// Efficiency bound (docs/grading.md, "Efficiency"): the traversals' CPU time at most this share
// of a brute force's over the same queries, plus kPhaseSlackSeconds per query phase. A correct
// BVH traversal takes a few percent of a brute force on the largest test scene; a brute force
// through the framework's intersect takes about twice the oracle's time.
inline constexpr double kBruteForceShare = 0.25;
inline constexpr double kPhaseSlackSeconds = 0.005;
inline constexpr size_t kTimedOracleRays = 200;
// Relative tolerance of the SAH cost for the SAH builders.
inline constexpr double kSahTolerance = 1e-4;

std::vector<TestGroup> bvhConfigGroups(const BvhConfig& config, GradingContext& context);

}  // namespace rtlab::grader
