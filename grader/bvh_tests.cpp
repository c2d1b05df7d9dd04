#include "grader/bvh_tests.h"

#include "grader/bvh_structure.h"
#include "grader/scene_codec.h"
#include "grader/visit_order.h"
#include "grader/worker/task_inputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rtlab::grader {
namespace {

constexpr const char* kStubOrdered = "a1 intersectBvh (assignments/a1_bvh/bvh_traverse.cpp)";
constexpr const char* kStubRecursive = "a1 intersectBvhRecursive (assignments/a1_bvh/bvh_traverse.cpp)";
constexpr const char* kStubOccluded = "a1 occludedBvh (assignments/a1_bvh/bvh_traverse.cpp)";

using worker::RawQuery;

// --- Worker phases ----------------------------------------------------------------------------

ChildPhase buildPhase(const BvhConfig& config, const Scene& scene) {
    ByteWriter input;
    writeScene(scene, input);
    input.put(config.options);
    return makePhase(config.buildStub, worker::kTaskBvhBuild, std::move(input));
}

enum class Query { Ordered, Recursive, Occluded };

ChildPhase queryPhase(Query query, const std::vector<Ray>& rays) {
    const char* stub = query == Query::Ordered ? kStubOrdered : query == Query::Recursive ? kStubRecursive : kStubOccluded;
    auto wire = query == Query::Ordered ? worker::BvhQuery::Ordered : query == Query::Recursive ? worker::BvhQuery::Recursive : worker::BvhQuery::Occluded;
    ByteWriter input;
    input.put<uint8_t>(static_cast<uint8_t>(wire));
    input.putVector(rays);
    return makePhase(stub, worker::kTaskBvhQuery, std::move(input));
}

// The visit-order test runs on this many of a scene's closest-hit rays.
constexpr size_t kVisitRays = 300;

ChildPhase visitsPhase(const std::vector<Ray>& rays) {
    ByteWriter input;
    input.putVector(rays);
    return makePhase(kStubOrdered, worker::kTaskBvhVisits, std::move(input));
}

// --- Parent side ------------------------------------------------------------------------------

// The visit-order verdict on the student's tree (visit_order.h), once the structure is valid.
void scoreVisitOrder(const PhaseOutcome& outcome, const Bvh* bvh, const PreparedScene& scene, const std::vector<Ray>& rays,
                     TestResult& result, const std::string& tag) {
    if (failedPhaseResult(outcome, result)) return;
    if (!bvh) {
        markFailed(result, "the structure is invalid, so the order of its leaves means nothing");
        return;
    }
    ByteReader in(outcome.data);
    std::vector<std::vector<uint32_t>> tested(rays.size());
    for (std::vector<uint32_t>& list : tested) {
        auto n = in.get<uint32_t>();
        if (n > worker::kMaxListedTests) throw WireError("a list of tests longer than the limit");
        for (uint32_t i = 0; i < n; ++i) list.push_back(in.get<uint32_t>());
        for (uint32_t prim : list)
            if (prim >= scene.primBounds.size()) throw WireError("a tested primitive out of range");
    }
    VisitOrderVerdict verdict = judgeVisitOrder(*bvh, scene.test.scene, rays, tested);
    for (const std::string& p : verdict.problems) result.details.push_back(tag + p);
    std::string line = tag + std::to_string(verdict.wrong) + " of " + std::to_string(verdict.graded) +
                       " rays visit leaves out of order (rays meeting a box edge within rounding are not graded; " +
                       std::to_string(allowedVisitOrderErrors(verdict.graded)) + " allowed)";
    if (verdict.wrong <= allowedVisitOrderErrors(verdict.graded)) markPassed(result, line);
    else markFailed(result, line + "; first: " + verdict.problems.front());
}

std::optional<Bvh> readBvh(const PhaseOutcome& outcome, size_t primCount, std::string* problem) {
    try {
        ByteReader in(outcome.data);
        Bvh bvh;
        bvh.nodes = in.getVector<BvhNode>(4 * primCount + 16);
        bvh.primIndices = in.getVector<uint32_t>(4 * primCount + 16);
        return bvh;
    } catch (const WireError& e) {
        *problem = std::string("the build sent malformed results: ") + e.what();
        return std::nullopt;
    }
}

TestGroup hitSetGroup(const BvhConfig& config, std::shared_ptr<PreparedScene> scene, GradingContext& context) {
    TestGroup group;
    group.assignment = config.assignment;
    group.title = config.assignment + " " + config.label + " on " + scene->test.id;
    group.phases = {buildPhase(config, scene->test.scene), queryPhase(Query::Ordered, scene->rays.rays),
                    queryPhase(Query::Occluded, scene->anyHitRays)};
    if (config.recursive) group.phases.push_back(queryPhase(Query::Recursive, scene->rays.rays));
    auto visitRays = std::make_shared<std::vector<Ray>>(scene->rays.rays.begin(),
                                                        scene->rays.rays.begin() + std::min(kVisitRays, scene->rays.rays.size()));
    const size_t visitPhase = group.phases.size();
    if (config.visitOrder) group.phases.push_back(visitsPhase(*visitRays));

    group.score = [config, scene, visitRays, visitPhase, &context](const SandboxRun& run, std::vector<TestResult>& results) {
        const std::string prefix = config.assignment + "/" + config.label + "/";
        const std::string tag = "[" + scene->test.id + "] ";
        const std::string key = config.label + "/" + scene->test.id;
        auto result = [&](const std::string& name) {
            TestResult r = makeResult(config.assignment, prefix + name);
            if (!scene->test.note.empty()) r.details.push_back(tag + scene->test.note);
            return r;
        };
        TestResult structure = result("structure"), sah = result("sah-cost"), closest = result("closest-hits"),
                   anyHit = result("any-hits"), efficiency = result("efficiency");
        std::optional<Bvh> bvh;
        bool structureValid = false;
        if (!failedPhaseResult(run.phases[0], structure)) {
            std::string problem;
            bvh = readBvh(run.phases[0], scene->primBounds.size(), &problem);
            if (!bvh) {
                markFailed(structure, problem);
            } else {
                BvhStructureReport report = checkBvhStructure(*bvh, scene->primBounds, true);
                structureValid = report.problems.empty();
                for (const std::string& p : report.problems) structure.details.push_back(tag + p);
                if (structureValid)
                    markPassed(structure, tag + std::to_string(bvh->nodes.size()) + " nodes, " + std::to_string(report.leaves) +
                                        " leaves, depth " + std::to_string(report.depth));
                else
                    markFailed(structure, std::to_string(report.problemCount) + " problems; first: " + report.problems.front());
            }
        }
        sah.status = structure.status == TestStatus::NotStarted ? TestStatus::NotStarted : TestStatus::Failed;
        sah.reason = structure.reason;
        efficiency.status = sah.status;
        efficiency.reason = structure.reason;

        auto ordered = readQueries(run.phases[1], scene->rays.rays.size(), closest);
        auto occluded = readQueries(run.phases[2], scene->anyHitRays.size(), anyHit);
        size_t wrongHits = 0;
        if (ordered) wrongHits += judgeClosestHits(*scene, *ordered, closest, tag);
        if (occluded) wrongHits += judgeOcclusion(*scene, *occluded, anyHit, tag);
        TestResult recursive = result("recursive-hits");
        if (config.recursive)
            if (auto answers = readQueries(run.phases[3], scene->rays.rays.size(), recursive))
                wrongHits += judgeClosestHits(*scene, *answers, recursive, tag);

        if (structureValid) {
            double cost = graderSahCost(*bvh);
            ReferenceData& reference = context.reference;
            if (reference.writing()) {
                if (wrongHits == 0 && ordered && occluded) {
                    reference.record(key, BvhReference{scene->sha256, cost, meanWork(*ordered), meanWork(*occluded)});
                    markPassed(sah, tag + "SAH cost " + formatNumber(cost) + " recorded as the reference");
                } else {
                    markFailed(sah, "not recorded: this implementation fails its own hit-set tests");
                }
            } else {
                std::string whyNot;
                auto ref = reference.find(key, scene->sha256, &whyNot);
                if (!ref) {
                    markFailed(sah, whyNot);
                } else {
                    double tolerance = config.exactSah ? 1e-12 : kSahTolerance;
                    std::string line = tag + "SAH cost " + formatNumber(cost) + ", reference " + formatNumber(ref->sahCost) +
                                       " (" + (config.exactSah ? "must match exactly" : "within 1e-4 relative") + ")";
                    if (std::abs(cost - ref->sahCost) <= tolerance * ref->sahCost) markPassed(sah, line);
                    else {
                        sah.details.push_back(line);
                        markFailed(sah, line);
                    }
                    if (ordered && occluded)
                        efficiency.details.push_back(tag + "framework counters (feedback, not evidence): node visits + primitive tests per ray: closest " +
                                                     formatNumber(meanWork(*ordered)) + " (reference " + formatNumber(ref->closestWorkPerRay) +
                                                     "), any-hit " + formatNumber(meanWork(*occluded)) + " (reference " +
                                                     formatNumber(ref->occludedWorkPerRay) + ")");
                }
            }
            if (ordered && occluded && wrongHits == 0) {
                size_t queries = scene->rays.rays.size() * (config.recursive ? 2 : 1) + scene->anyHitRays.size() +
                                 (config.visitOrder ? visitRays->size() : 0);
                judgeEfficiency(*scene, run, 1, queries, efficiency, tag);
            } else {
                markFailed(efficiency, "the traversal must return the right hits before its speed counts: " +
                                     (!ordered ? closest.reason : !occluded ? anyHit.reason : "some hits are wrong"));
            }
        } else if (structure.status != TestStatus::NotStarted && bvh) {
            markFailed(sah, "the structure is invalid, so its SAH cost means nothing");
            markFailed(efficiency, sah.reason);
        }
        TestResult visits = result("visit-order");
        if (config.visitOrder) scoreVisitOrder(run.phases[visitPhase], structureValid ? &*bvh : nullptr, *scene, *visitRays, visits, tag);
        bool timed = scene->bruteForceSecondsPerRay > 0.0;
        for (TestResult* r : {&structure, &sah, &closest, &recursive, &anyHit, &efficiency, &visits})
            if ((r != &recursive || config.recursive) && (r != &efficiency || timed) && (r != &visits || config.visitOrder))
                results.push_back(std::move(*r));
    };
    return group;
}

// --- Degenerate inputs (stress catalogue) -----------------------------------------------------

struct StressRay {
    Ray ray;
    bool occlusionQuery;       // any-hit with ray.tMax instead of closest hit
    bool hit;                  // exact expectation
    std::vector<uint32_t> prims;  // allowed primitives when hit
    float t;
};

struct StressScene {
    std::string id;
    Scene scene;
    std::vector<StressRay> rays;
};

std::vector<StressScene> stressScenes() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<StressScene> scenes;
    auto ray = [](Vec3 o, Vec3 d, float tMax = kInfinity) {
        Ray r;
        r.origin = o;
        r.direction = d;
        r.tMax = tMax;
        return r;
    };
    {
        SceneBuilder b;
        for (int a = 1; a <= 64; ++a) b.addTriangle({-float(a), -1, -1}, {float(a), -1, 1}, {0, 2, 0});
        scenes.push_back({"BVH-01 identical centroids", b.take(), {{ray({0.5f, 0, 10}, {0, 0, -1}), false, true, {0}, 9.5f}}});
    }
    {
        SceneBuilder b;
        for (int k = 0; k < 64; ++k) b.addTriangle({float(k), -1, -100}, {float(k), 1, -100}, {float(k), 0, 200});
        scenes.push_back({"BVH-02 zero centroid extent on the longest axis", b.take(), {{ray({-1, 0, 0}, {1, 0, 0}), false, true, {0}, 1}}});
    }
    {
        SceneBuilder b;
        std::vector<StressRay> rays;
        const float centres[] = {0.0f, 0.5f, 1.0f, 3.0f, 3.1f};
        for (uint32_t i = 0; i < 5; ++i) {
            float cx = centres[i];
            b.addTriangle({cx - 0.1f, 5.0f * i, 0}, {cx + 0.1f, 5.0f * i, 0}, {cx, 5.0f * i + 0.1f, 0.1f});
            rays.push_back({ray({cx, 5.0f * i + 0.05f, 1}, {0, 0, -1}), false, true, {i}, 0.95f});
        }
        scenes.push_back({"BVH-03 bucket index clamp", b.take(), rays});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        scenes.push_back({"BVH-07 one primitive", b.take(), {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, {0}, 1}}});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        scenes.push_back({"BVH-07 two identical primitives", b.take(), {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, {0, 1}, 1}}});
    }
    {
        SceneBuilder b;
        for (int i = 0; i < 10; ++i) b.addTriangle({float(i), 0, 0}, {i + 0.5f, 0, 0}, {float(i + 1), 0, 0});
        std::vector<StressRay> rays = {{ray({2.25f, 0, 5}, {0, 0, -1}), false, false, {}, 0},
                                       {ray({-1, 0, 0}, {1, 0, 0}), false, false, {}, 0},
                                       {ray({2.25f, 0, 5}, {0, 0, -1}, 10), true, false, {}, 0}};
        scenes.push_back({"BVH-08 degenerate primitives only", b.take(), rays});
        SceneBuilder mixed;
        for (int i = 0; i < 10; ++i) mixed.addTriangle({float(i), 0, 0}, {i + 0.5f, 0, 0}, {float(i + 1), 0, 0});
        mixed.addTriangle({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
        scenes.push_back({"BVH-08 degenerate and valid", mixed.take(), {{ray({1, 1, 5}, {0, 0, -1}), false, true, {10}, 6}}});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
        b.addTriangle({1, 1, 1}, {1, 1, 1}, {1, 1, 1});
        b.addTriangle({0, 0, 0}, {0, 0, 0}, {1, 0, 0});
        b.addTriangle({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
        scenes.push_back({"TRI-12 degenerate triangles", b.take(), {{ray({1, 1, 5}, {0, 0, -1}), false, true, {3}, 6}}});
    }
    {
        // Midpoint splits on centroids x = 2^-k peel two primitives off per level while the
        // smallest centroid is below the midpoint's rounding, then one: 150 of them (the last
        // ones subnormal) reach the depth cap. A ray along +x meets both children at every
        // level and keeps one pending per level: a traversal stack smaller than kMaxBvhDepth
        // overflows. Float rounds 1 + 2^-k to 1 for k >= 24, so those primitives tie at t = 1.
        SceneBuilder b;
        std::vector<uint32_t> tied;
        for (int k = 0; k < 150; ++k) {
            float x = std::ldexp(1.0f, -k);
            b.addTriangle({x, -1, -1}, {x, 1, -1}, {x, 0, 1});
            if (k >= 20) tied.push_back(uint32_t(k));
        }
        scenes.push_back({"BVH-10 a tree as deep as the cap", b.take(), {{ray({-1, 0, 0}, {1, 0, 0}), false, true, tied, 1}}});
    }
    {
        // More identical primitives than a leaf's 16-bit primCount holds: splitNode makes this
        // a leaf (equal centroids), and buildBvh must split it anyway.
        SceneBuilder b;
        std::vector<uint32_t> all;
        for (uint32_t i = 0; i < 70000; ++i) {
            b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
            all.push_back(i);
        }
        scenes.push_back({"BVH-11 70000 identical primitives", b.take(), {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, all, 1}}});
    }
    {
        // Triangles of side 2^62 spread over 31 * 2^62: the root's surface area, 62 * 2^124,
        // overflows float (FLT_MAX < 2^128) while every edge function and a leaf's area do not,
        // so only SAH costs computed in float go wrong (all infinite: no split found).
        SceneBuilder b;
        const float s = 0x1p62f;
        for (int k = 0; k < 16; ++k) b.addTriangle({k * 2 * s, 0, 0}, {k * 2 * s + s, 0, 0}, {k * 2 * s, s, 0});
        scenes.push_back({"BVH-12 coordinates near 2^62", b.take(), {{ray({0x1p60f, 0x1p60f, 1}, {0, 0, -1}), false, true, {0}, 1}}});
    }
    for (float bad : {nan, kInfinity}) {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {bad, 1, 0});
        b.addTriangle({0, 0, -1}, {1, 0, -1}, {0, 1, -1});
        std::vector<StressRay> rays = {{ray({0.2f, 0.2f, 1}, {0, 0, -1}), false, true, {1}, 2},
                                       {ray({0.2f, 0.2f, 1}, {0, 0, -1}, 1.5f), true, false, {}, 0}};
        scenes.push_back({std::string("TRI-13 ") + (std::isnan(bad) ? "NaN" : "infinite") + " vertex", b.take(), rays});
    }
    return scenes;
}

TestGroup stressGroup(const BvhConfig& config, std::shared_ptr<StressScene> stress) {
    auto closestRays = std::make_shared<std::vector<Ray>>(), occlusionRays = std::make_shared<std::vector<Ray>>();
    for (const StressRay& r : stress->rays) (r.occlusionQuery ? occlusionRays : closestRays)->push_back(r.ray);
    TestGroup group;
    group.assignment = config.assignment;
    group.title = config.assignment + " " + config.label + " on " + stress->id;
    group.phases = {buildPhase(config, stress->scene), queryPhase(Query::Ordered, *closestRays), queryPhase(Query::Occluded, *occlusionRays)};
    group.score = [config, stress, closestRays, occlusionRays](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(config.assignment, config.assignment + "/" + config.label + "/degenerate-inputs");
        const std::string tag = "[" + stress->id + "] ";
        std::vector<std::string> problems;
        if (failedPhaseResult(run.phases[0], result)) {
            result.reason = tag + result.reason;
            results.push_back(std::move(result));
            return;
        }
        std::vector<Bounds3f> primBounds;
        for (uint32_t i = 0; i < stress->scene.primitiveCount(); ++i) primBounds.push_back(stress->scene.primitiveBounds(i));
        std::string wireProblem;
        auto bvh = readBvh(run.phases[0], primBounds.size(), &wireProblem);
        if (!bvh) {
            problems.push_back(wireProblem);
        } else {
            BvhStructureReport report = checkBvhStructure(*bvh, primBounds, false);
            for (const std::string& p : report.problems) problems.push_back(p);
            // Leaf sizes mean something only in a valid tree (a broken one may even have cycles).
            if (report.problems.empty())
                for (const std::string& p : oversizedLeaves(*bvh, primBounds, config.options.maxLeaf)) problems.push_back(p);
        }
        TestResult scratch;
        auto closest = readQueries(run.phases[1], closestRays->size(), scratch);
        auto occluded = readQueries(run.phases[2], occlusionRays->size(), scratch);
        if (!closest || !occluded) problems.push_back(scratch.reason);
        size_t ci = 0, oi = 0;
        for (const StressRay& r : stress->rays) {
            const RawQuery* a = r.occlusionQuery ? (occluded ? &(*occluded)[oi++] : nullptr) : (closest ? &(*closest)[ci++] : nullptr);
            if (!a) continue;
            std::string got;
            bool right;
            if (r.occlusionQuery) {
                right = (a->prim != 0) == r.hit;
                got = a->prim ? "occluded" : "not occluded";
            } else if (!r.hit) {
                right = a->prim == kNoHit;
                got = right ? "a miss" : "prim " + std::to_string(a->prim) + " at t=" + formatNumber(a->t);
            } else {
                bool allowed = std::find(r.prims.begin(), r.prims.end(), a->prim) != r.prims.end();
                right = allowed && std::abs(a->t - r.t) <= 1e-5f * std::max(1.0f, r.t);
                got = a->prim == kNoHit ? "a miss" : "prim " + std::to_string(a->prim) + " at t=" + formatNumber(a->t);
            }
            if (right) continue;
            std::string expected = r.occlusionQuery ? (r.hit ? "occluded" : "not occluded")
                                   : r.hit          ? "a hit at t=" + formatNumber(r.t) + " on prim " + std::to_string(r.prims.front())
                                                    : "a miss";
            problems.push_back(describeRay(r.ray) + ": expected " + expected + ", got " + got);
        }
        for (const std::string& p : problems) result.details.push_back(tag + p);
        if (problems.empty()) markPassed(result, tag + "built and answered correctly");
        else markFailed(result, tag + problems.front());
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace

std::vector<TestGroup> bvhConfigGroups(const BvhConfig& config, GradingContext& context) {
    std::vector<TestGroup> groups;
    for (const auto& scene : hitSetScenes(context).list) groups.push_back(hitSetGroup(config, scene, context));
    for (StressScene& stress : stressScenes()) groups.push_back(stressGroup(config, std::make_shared<StressScene>(std::move(stress))));
    return groups;
}

}  // namespace rtlab::grader
