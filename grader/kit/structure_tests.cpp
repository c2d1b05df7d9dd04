#include "grader/kit/structure_tests.h"

#include "framework/core/error.h"
#include "grader/kit/failed_ray_cases.h"

#include <algorithm>
#include <cmath>

namespace rtlab::grader {
namespace {

// The visit-order test runs on this many of a scene's closest-hit rays.
constexpr size_t kVisitRays = 300;
// A traversal whose answers on the grader's structure hit primitives it does not hold along
// the ray on this many rays or more walks something else: its answers elsewhere prove nothing.
// (A correct traversal never does; a wrong one rarely, by visiting a cell off the ray.)
constexpr size_t kUnfollowedRays = 3;

// A query phase: `structure` (empty for the structure the build made), then u8 QueryKind, [Ray].
ChildPhase queryPhase(const QueryTest& query, const std::string& task, const std::vector<uint8_t>& structure, const std::vector<Ray>& rays) {
    ByteWriter input;
    input.bytes() = structure;
    input.put<uint8_t>(static_cast<uint8_t>(query.kind));
    input.putVector(rays);
    // With no rays to ask, the task calls no stub.
    return makePhase(query.stub, task, std::move(input), rays.empty() ? "" : query.stub);
}

ChildPhase queryPhase(const StructurePlugin& plugin, const QueryTest& query, const std::vector<Ray>& rays) {
    return queryPhase(query, plugin.queryTask, {}, rays);
}

const std::vector<Ray>& raysOf(const PreparedScene& scene, const QueryTest& query) {
    return query.kind == worker::QueryKind::Occluded ? scene.anyHitRays : scene.rays.rays;
}

// A given-structure phase's answers judged ray by ray (given_structure.h) and folded into the
// hit-set test `result`: a wrong ray fails it as a wrong ray of the scene does. Returns how many
// answers hit primitives the structure does not hold along their ray.
size_t scoreGivenAnswers(const std::shared_ptr<PreparedScene>& prepared, const GivenStructureJudge& judge, const QueryTest& test,
                         const PhaseOutcome& outcome, TestResult& result, const std::string& tag) {
    PreparedScene& scene = *prepared;
    const std::string where = tag + "on a structure the grader built, with primitives left out of some leaves: ";
    bool occluded = test.kind == worker::QueryKind::Occluded;
    const std::vector<Ray>& rays = raysOf(scene, test);
    TestResult given;
    auto answers = readQueries(outcome, rays.size(), given);
    if (!answers) {
        if (result.status == TestStatus::Passed) {
            result.status = given.status;
            result.fraction = 0.0;
            result.reason = where + given.reason;
        }
        return 0;
    }
    size_t wrong = 0, unheld = 0;
    std::string first;
    for (size_t i = 0; i < answers->size(); ++i) {
        const worker::RawQuery& a = (*answers)[i];
        std::string problem = occluded ? judge.judgeOccluded(*scene.anyHitJudge, i, rays[i], a.prim != 0)
                                       : judge.judgeClosest(*scene.judge, i, rays[i], HitAnswer{a.prim, a.t});
        if (problem.empty()) continue;
        unheld += problem.find(GivenStructureJudge::kNotInStructure) != std::string::npos;
        std::string line = where + "ray " + std::to_string(i) + " " + describeRay(rays[i]) + ": " + problem;
        // The viewer shows the ray and the answer; what the grader's structure held is in the note.
        if (result.failedCases.size() < kViewerCasesPerTest) {
            WrongRay wrongRay{i, where + problem};
            std::string title = tag + test.name + " on the grader's structure: ray " + std::to_string(i);
            FailedCase failed = occluded ? anyHitCase(prepared, rays[i], wrongRay, a.prim != 0, title)
                                         : closestHitCase(prepared, *scene.judge, rays[i], wrongRay, a, title);
            // The oracle's hit may be one the grader's structure left out: the note says what was due.
            failed.rays.back().expected = CaseAnswer{};
            addFailedCase(result, std::move(failed));
        }
        if (wrong++ < 5) result.details.push_back(line);
        if (first.empty()) first = line;
    }
    if (wrong == 0) result.details.push_back(where + "all " + std::to_string(rays.size()) + " rays follow it");
    else if (result.status == TestStatus::Passed) markFailed(result, std::to_string(wrong) + " of " + std::to_string(rays.size()) + " rays wrong; first: " + first);
    return unheld;
}

double cpuSeconds(const SandboxRun& run, size_t first, size_t end) {
    double sum = 0.0;
    for (size_t k = first; k < end; ++k) sum += run.phases[k].cpuSeconds;
    return sum;
}

const QueryTest& queryOfKind(const StructurePlugin& plugin, worker::QueryKind kind) {
    for (const QueryTest& q : plugin.queries)
        if (q.kind == kind) return q;
    throw Error(plugin.assignment + " " + plugin.label + ": the plugin grades no traversal of this kind");
}

// A result's status and reason copied from another, failed or not started, as the reason this
// one cannot be judged.
void failLike(TestResult& result, const TestResult& cause, const std::string& reason) {
    result.status = cause.status == TestStatus::NotStarted ? TestStatus::NotStarted : TestStatus::Failed;
    result.fraction = 0.0;
    result.reason = reason;
}

// The lists a visits phase sent: per ray the primitives tested, in order.
std::optional<std::vector<std::vector<uint32_t>>> readVisits(const PhaseOutcome& outcome, size_t rays, size_t primCount,
                                                             TestResult& result) {
    if (failedPhaseResult(outcome, result)) return std::nullopt;
    try {
        ByteReader in(outcome.data);
        std::vector<std::vector<uint32_t>> tested(rays);
        for (std::vector<uint32_t>& list : tested) {
            auto n = in.get<uint32_t>();
            if (n > worker::kMaxListedTests) throw WireError("a list of tests longer than the limit");
            for (uint32_t i = 0; i < n; ++i) list.push_back(in.get<uint32_t>());
            for (uint32_t prim : list)
                if (prim >= primCount) throw WireError("a tested primitive out of range");
        }
        return tested;
    } catch (const WireError& e) {
        markFailed(result, std::string("sent malformed results: ") + e.what());
        return std::nullopt;
    }
}

// The structure verdict; the report is kept for the cost and visit-order tests.
std::optional<StructureReport> scoreStructure(const StructurePlugin& plugin, const PhaseOutcome& build,
                                              const std::shared_ptr<PreparedScene>& scene, TestResult& structure, const std::string& tag,
                                              std::optional<StructureView>& view, std::optional<std::array<int, 3>>& gridResolution) {
    if (failedPhaseResult(build, structure)) return std::nullopt;
    StructureReport report = plugin.check(build, scene->primBounds, CheckScope::HitSetScene);
    for (const std::string& p : report.problems) structure.details.push_back(tag + p);
    if (!plugin.drawing.empty()) {
        view = report.view;
        gridResolution = report.gridResolution;
    }
    if (!report.problems.empty()) {
        FailedCase failed;
        failed.title = tag + plugin.assignment + "/" + plugin.label + "/structure";
        for (size_t k = 0; k < report.problems.size() && k < kViewerRaysPerCase; ++k) failed.notes.push_back(report.problems[k]);
        failed.scene = sharedScene(scene);
        if (view) {
            failed.accelerator = plugin.drawing;
            failed.draw = plugin.draw;
            failed.structure = view;
            failed.gridResolution = gridResolution;
        }
        addFailedCase(structure, std::move(failed));
        size_t count = std::max(report.problemCount, report.problems.size());
        markFailed(structure, (count > 1 ? std::to_string(count) + " problems; first: " : "") + tag + report.problems.front());
        return std::nullopt;
    }
    markPassed(structure, tag + report.summary);
    return report;
}

// The cost test: the grader's own cost of the structure against the reference's, or, when the
// reference is being written, recorded as it.
void scoreCost(const CostTest& test, double cost, const std::optional<StructureReference>& reference, const std::string& whyNot,
               bool writing, bool hitsRight, TestResult& result, const std::string& tag) {
    if (writing) {
        if (hitsRight) markPassed(result, tag + test.what + " " + formatNumber(cost) + " recorded as the reference");
        else markFailed(result, "not recorded: this implementation fails its own hit-set tests");
        return;
    }
    if (!reference || !reference->cost) {
        markFailed(result, reference ? "the reference data has no " + test.what : whyNot);
        return;
    }
    std::string line = tag + test.what + " " + formatNumber(cost) + ", reference " + formatNumber(*reference->cost) + " (" + test.rule + ")";
    if (std::abs(cost - *reference->cost) <= test.tolerance * std::abs(*reference->cost)) {
        markPassed(result, line);
    } else {
        result.details.push_back(line);
        markFailed(result, line);
    }
}

void scoreVisitOrder(const StructureReport* report, const PhaseOutcome& outcome, const std::shared_ptr<PreparedScene>& prepared,
                     const std::vector<Ray>& rays, TestResult& result, const std::string& tag, const std::function<FailedCase(FailedCase)>& withStructure) {
    const PreparedScene& scene = *prepared;
    auto tested = readVisits(outcome, rays.size(), scene.primBounds.size(), result);
    if (!tested) return;
    if (!report) {
        markFailed(result, "the structure is invalid, so the order of its leaves means nothing");
        return;
    }
    VisitOrderVerdict verdict = report->judgeVisits(scene.test.scene, rays, *tested);
    for (const std::string& p : verdict.problems) result.details.push_back(tag + p);
    std::string line = tag + std::to_string(verdict.wrong) + " of " + std::to_string(verdict.graded) +
                       " rays visit leaves out of order (rays meeting a box edge within rounding are not graded; " +
                       std::to_string(allowedVisitOrderErrors(verdict.graded)) + " allowed)";
    if (verdict.wrong <= allowedVisitOrderErrors(verdict.graded)) {
        markPassed(result, line);
        return;
    }
    markFailed(result, line + "; first: " + verdict.problems.front());
    for (size_t k = 0; k < verdict.wrongRays.size(); ++k) {
        size_t r = verdict.wrongRays[k];
        FailedCase failed;
        failed.title = tag + "visit-order: ray " + std::to_string(r);
        failed.notes.push_back(verdict.problems[k]);
        failed.scene = sharedScene(prepared);
        CaseRay& ray = failed.rays.emplace_back();
        ray.ray = rays[r];
        ray.label = "ray " + std::to_string(r) + ": the primitives its closest-hit walk tested, in order";
        ray.studentTrace = visitTrace((*tested)[r], TraceOpKind::PrimitiveTest);
        addFailedCase(result, withStructure(std::move(failed)));
    }
}

// --- Degenerate inputs ------------------------------------------------------------------------

// What one stress ray's answer should have been, or an empty string when it is right.
std::string stressProblem(const StressRay& r, const worker::RawQuery& a) {
    std::string got;
    bool right;
    if (r.occlusionQuery) {
        right = (a.prim != 0) == r.hit;
        got = a.prim ? "occluded" : "not occluded";
    } else if (!r.hit) {
        right = a.prim == kNoHit;
        got = right ? "a miss" : "prim " + std::to_string(a.prim) + " at t=" + formatNumber(a.t);
    } else {
        bool allowed = std::find(r.prims.begin(), r.prims.end(), a.prim) != r.prims.end();
        right = allowed && std::abs(a.t - r.t) <= 1e-5f * std::max(1.0f, r.t);
        got = a.prim == kNoHit ? "a miss" : "prim " + std::to_string(a.prim) + " at t=" + formatNumber(a.t);
    }
    if (right) return "";
    std::string expected = r.occlusionQuery ? (r.hit ? "occluded" : "not occluded")
                           : r.hit          ? "a hit at t=" + formatNumber(r.t) + " on prim " + std::to_string(r.prims.front())
                                            : "a miss";
    return describeRay(r.ray) + ": expected " + expected + ", got " + got;
}

TestGroup degenerateGroup(const StructurePlugin& plugin, std::shared_ptr<StressScene> stress) {
    auto closestRays = std::make_shared<std::vector<Ray>>(), occlusionRays = std::make_shared<std::vector<Ray>>();
    for (const StressRay& r : stress->rays) (r.occlusionQuery ? occlusionRays : closestRays)->push_back(r.ray);
    TestGroup group{plugin.assignment,
                    plugin.assignment + " " + plugin.label + " on " + stress->id,
                    {plugin.build(stress->scene), queryPhase(plugin, queryOfKind(plugin, worker::QueryKind::Closest), *closestRays),
                     queryPhase(plugin, queryOfKind(plugin, worker::QueryKind::Occluded), *occlusionRays)},
                    {}};
    group.score = [plugin, stress, closestRays, occlusionRays](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(plugin.assignment, plugin.assignment + "/" + plugin.label + "/degenerate-inputs");
        const std::string tag = "[" + stress->id + "] ";
        if (failedPhaseResult(run.phases[0], result)) {
            result.reason = tag + result.reason;
            results.push_back(std::move(result));
            return;
        }
        std::vector<Bounds3f> primBounds;
        for (uint32_t i = 0; i < stress->scene.primitiveCount(); ++i) primBounds.push_back(stress->scene.primitiveBounds(i));
        std::vector<std::string> problems = plugin.check(run.phases[0], primBounds, CheckScope::DegenerateScene).problems;
        TestResult scratch;
        auto closest = readQueries(run.phases[1], closestRays->size(), scratch);
        auto occluded = readQueries(run.phases[2], occlusionRays->size(), scratch);
        if (!closest || !occluded) problems.push_back(scratch.reason);
        size_t ci = 0, oi = 0;
        for (const StressRay& r : stress->rays) {
            const std::optional<std::vector<worker::RawQuery>>& answers = r.occlusionQuery ? occluded : closest;
            size_t index = r.occlusionQuery ? oi++ : ci++;
            if (!answers) continue;
            std::string problem = stressProblem(r, (*answers)[index]);
            if (!problem.empty()) problems.push_back(problem);
        }
        for (const std::string& p : problems) result.details.push_back(tag + p);
        if (problems.empty()) markPassed(result, tag + "built and answered correctly");
        else markFailed(result, tag + problems.front());
        result.needsFollowedStructure = true;
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace

TestGroup structureSceneGroup(const StructurePlugin& plugin, std::shared_ptr<PreparedScene> scene, GradingContext& context) {
    TestGroup group{plugin.assignment, plugin.assignment + " " + plugin.label + " on " + scene->test.id, {plugin.build(scene->test.scene)}, {}};
    for (const QueryTest& q : plugin.queries) group.phases.push_back(queryPhase(plugin, q, raysOf(*scene, q)));
    auto visitRays = std::make_shared<std::vector<Ray>>(scene->rays.rays.begin(),
                                                        scene->rays.rays.begin() + std::min(kVisitRays, scene->rays.rays.size()));
    if (!plugin.visitsTask.empty()) {
        ByteWriter input;
        input.putVector(*visitRays);
        group.phases.push_back(makePhase(plugin.visitsStub, plugin.visitsTask, std::move(input)));
    }
    // Phases from firstGiven on run the traversals on the grader's own structure.
    const size_t firstGiven = group.phases.size();
    std::shared_ptr<const GivenStructureJudge> givenJudge;
    if (plugin.given) {
        GivenStructure given = plugin.given(scene->test.scene, context.structureKey);
        for (const QueryTest& q : plugin.queries) group.phases.push_back(queryPhase(q, plugin.givenQueryTask, given.encoded, raysOf(*scene, q)));
        givenJudge = std::make_shared<GivenStructureJudge>(std::move(given.leaves), scene->test.scene);
    }

    group.score = [plugin, scene, visitRays, givenJudge, firstGiven, &context](const SandboxRun& run, std::vector<TestResult>& results) {
        const std::string tag = "[" + scene->test.id + "] ";
        auto result = [&](const std::string& name) {
            TestResult r = makeResult(plugin.assignment, plugin.assignment + "/" + plugin.label + "/" + name);
            if (!scene->test.note.empty()) r.details.push_back(tag + scene->test.note);
            return r;
        };
        TestResult structure = result("structure");
        std::optional<StructureView> view;  // the student's, for the viewer cases
        std::optional<std::array<int, 3>> gridResolution;
        std::optional<StructureReport> report = scoreStructure(plugin, run.phases[0], scene, structure, tag, view, gridResolution);
        // A wrong ray's viewer case: the ray through the student's structure.
        auto withStructure = [&](FailedCase failed) {
            failed.traceAccelerator = plugin.traceAccelerator;
            if (view) {
                failed.accelerator = plugin.drawing;
                failed.draw = plugin.draw;
                failed.structure = view;
                failed.gridResolution = gridResolution;
            }
            return failed;
        };

        // Every traversal's answers, judged ray by ray on the student's structure and on the
        // grader's; efficiency needs all of them right.
        std::vector<TestResult> hitTests;
        std::vector<worker::RawQuery> closestAnswers, occludedAnswers;
        size_t wrongHits = 0, queries = 0, unheld = 0;
        bool allAnswered = true;
        for (size_t q = 0; q < plugin.queries.size(); ++q) {
            const QueryTest& test = plugin.queries[q];
            bool occluded = test.kind == worker::QueryKind::Occluded;
            hitTests.push_back(result(test.name));
            queries += raysOf(*scene, test).size();
            auto answers = readQueries(run.phases[1 + q], raysOf(*scene, test).size(), hitTests.back());
            if (!answers) {
                allAnswered = false;
                continue;
            }
            std::vector<WrongRay> wrongRays;
            wrongHits += occluded ? judgeOcclusion(*scene, *answers, hitTests.back(), tag, &wrongRays)
                                  : judgeClosestHits(*scene, *answers, hitTests.back(), tag, &wrongRays);
            for (const WrongRay& w : wrongRays) {
                const Ray& ray = raysOf(*scene, test)[w.index];
                std::string title = tag + test.name + ": ray " + std::to_string(w.index);
                addFailedCase(hitTests.back(), withStructure(occluded ? anyHitCase(scene, ray, w, (*answers)[w.index].prim != 0, title)
                                                                      : closestHitCase(scene, *scene->judge, ray, w, (*answers)[w.index], title)));
            }
            if (givenJudge) unheld += scoreGivenAnswers(scene, *givenJudge, test, run.phases[firstGiven + q], hitTests.back(), tag);
            if (test.kind == worker::QueryKind::Closest) closestAnswers = *answers;
            if (occluded) occludedAnswers = *answers;
        }
        // Without a build there is nothing to traverse: the traversals are not started either,
        // whatever they did with the empty structure.
        if (structure.status == TestStatus::NotStarted)
            for (TestResult& t : hitTests) failLike(t, structure, structure.reason);
        bool hitsRight = allAnswered && wrongHits == 0 &&
                         std::all_of(hitTests.begin(), hitTests.end(), [](const TestResult& t) { return t.status == TestStatus::Passed; });
        if (unheld >= kUnfollowedRays)
            context.unfollowedStructure.try_emplace(plugin.assignment, tag + "on " + std::to_string(unheld) +
                                                                           " rays the traversal hit primitives the structure it was given "
                                                                           "does not hold along them (see " + plugin.assignment + "/" + plugin.label + "/" +
                                                                           plugin.queries.front().name + ")");

        // Reference values: recorded from a correct reference, otherwise read for comparison.
        ReferenceData& referenceData = context.reference;
        const std::string key = plugin.label + "/" + scene->test.id;
        std::string whyNot;
        std::optional<StructureReference> reference;
        if (referenceData.writing()) {
            if (report && hitsRight)
                referenceData.record(key, StructureReference{scene->sha256, report->cost, meanWork(closestAnswers), meanWork(occludedAnswers)});
        } else {
            reference = referenceData.find(key, scene->sha256, &whyNot);
        }

        TestResult cost = result(plugin.cost ? plugin.cost->name : "cost");
        if (plugin.cost) {
            if (!report) failLike(cost, structure, structure.status == TestStatus::NotStarted ? structure.reason
                                                                                                 : "the structure is invalid, so its cost means nothing");
            else scoreCost(*plugin.cost, report->cost.value_or(0.0), reference, whyNot, referenceData.writing(), hitsRight, cost, tag);
        }

        TestResult efficiency = result("efficiency");
        if (allAnswered) {
            std::string feedback = tag + "framework counters (feedback, not evidence): box tests, cell and plane steps + primitive tests per ray: closest " +
                                   formatNumber(meanWork(closestAnswers));
            if (reference) feedback += " (reference " + formatNumber(reference->closestWorkPerRay) + ")";
            feedback += ", any-hit " + formatNumber(meanWork(occludedAnswers));
            if (reference) feedback += " (reference " + formatNumber(reference->occludedWorkPerRay) + ")";
            efficiency.details.push_back(feedback);
        }
        size_t visitQueries = plugin.visitsTask.empty() ? 0 : visitRays->size();
        if (!report) failLike(efficiency, structure, structure.status == TestStatus::NotStarted ? structure.reason
                                                                                                  : "the structure is invalid, so its speed means nothing");
        else if (!hitsRight) {
            const TestResult* cause = &hitTests.front();
            for (const TestResult& t : hitTests)
                if (t.status != TestStatus::Passed) {
                    cause = &t;
                    break;
                }
            failLike(efficiency, *cause, "the traversal must return the right hits before its speed counts: " + cause->reason);
        } else {
            // Timed on the grader's structure, whose phases no submission can foresee: an answer
            // worked out before its phase (while building, say) would not fit it. Without one,
            // on the traversals of the student's own structure.
            std::vector<EfficiencyVerdict> verdicts;
            if (givenJudge)
                verdicts.push_back(measureEfficiency(*scene, cpuSeconds(run, firstGiven, run.phases.size()), run.phases.size() - firstGiven, queries,
                                                     tag + "traversal on the grader's structure"));
            else
                verdicts.push_back(measureEfficiency(*scene, cpuSeconds(run, 1, firstGiven), firstGiven - 1, queries + visitQueries, tag + "traversal"));
            auto slow = std::find_if(verdicts.begin(), verdicts.end(), [](const EfficiencyVerdict& v) { return !v.fast; });
            for (const EfficiencyVerdict& v : verdicts) efficiency.details.push_back(v.line);
            if (slow == verdicts.end()) markPassed(efficiency, "");
            else markFailed(efficiency, "the traversal is about as slow as a brute force: " + slow->line);
        }

        TestResult visits = result("visit-order");
        if (!plugin.visitsTask.empty()) {
            scoreVisitOrder(report ? &*report : nullptr, run.phases[firstGiven - 1], scene, *visitRays, visits, tag, withStructure);
            if (structure.status == TestStatus::NotStarted) failLike(visits, structure, structure.reason);
        }

        // What a private structure could answer: the hits and their speed, on every scene.
        for (TestResult& t : hitTests) t.needsFollowedStructure = true;
        efficiency.needsFollowedStructure = true;
        results.push_back(std::move(structure));
        if (plugin.cost) results.push_back(std::move(cost));
        for (TestResult& t : hitTests) results.push_back(std::move(t));
        if (scene->bruteForceSecondsPerRay > 0.0) results.push_back(std::move(efficiency));
        if (!plugin.visitsTask.empty()) results.push_back(std::move(visits));
    };
    return group;
}

std::vector<TestGroup> structureGroups(const StructurePlugin& plugin, GradingContext& context) {
    std::vector<TestGroup> groups;
    for (const auto& scene : hitSetScenes(context).list) groups.push_back(structureSceneGroup(plugin, scene, context));
    for (StressScene& stress : stressScenes())
        if (std::find(plugin.skipDegenerate.begin(), plugin.skipDegenerate.end(), stress.id) == plugin.skipDegenerate.end())
            groups.push_back(degenerateGroup(plugin, std::make_shared<StressScene>(std::move(stress))));
    return groups;
}

}  // namespace rtlab::grader
