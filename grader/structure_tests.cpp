#include "grader/structure_tests.h"

namespace rtlab::grader {

TestGroup structureSceneGroup(const StructurePlugin& plugin, std::shared_ptr<PreparedScene> scene) {
    TestGroup group{plugin.assignment, plugin.assignment + " " + plugin.label + " on " + scene->test.id,
                    {plugin.build(scene->test.scene), plugin.query(false, scene->rays.rays), plugin.query(true, scene->anyHitRays)},
                    {}};
    group.score = [plugin, scene](const SandboxRun& run, std::vector<TestResult>& results) {
        const std::string tag = "[" + scene->test.id + "] ";
        auto result = [&](const std::string& name) {
            TestResult r = makeResult(plugin.assignment, plugin.assignment + "/" + plugin.label + "/" + name);
            if (!scene->test.note.empty()) r.details.push_back(tag + scene->test.note);
            return r;
        };
        TestResult structure = result("structure"), closest = result("closest-hits"), anyHit = result("any-hits"),
                   efficiency = result("efficiency");
        if (!failedPhaseResult(run.phases[0], structure)) {
            StructureReport report = plugin.check(run.phases[0], scene->primBounds);
            for (const std::string& p : report.problems) structure.details.push_back(tag + p);
            if (report.problems.empty()) markPassed(structure, tag + report.summary);
            else markFailed(structure, tag + report.problems.front());
        }
        auto ordered = readQueries(run.phases[1], scene->rays.rays.size(), closest);
        auto occluded = readQueries(run.phases[2], scene->anyHitRays.size(), anyHit);
        size_t wrong = 0;
        if (ordered) wrong += judgeClosestHits(*scene, *ordered, closest, tag);
        if (occluded) wrong += judgeOcclusion(*scene, *occluded, anyHit, tag);
        if (ordered && occluded) {
            efficiency.details.push_back(tag + "framework counters (feedback, not evidence): box tests and cell steps + primitive tests per ray: closest " +
                                         formatNumber(meanWork(*ordered)) + ", any-hit " + formatNumber(meanWork(*occluded)));
            if (wrong == 0) judgeEfficiency(*scene, run, 1, scene->rays.rays.size() + scene->anyHitRays.size(), efficiency, tag);
            else markFailed(efficiency, "the traversal must return the right hits before its speed counts");
        } else {
            const TestResult& missing = !ordered ? closest : anyHit;
            efficiency.status = missing.status == TestStatus::NotStarted ? TestStatus::NotStarted : TestStatus::Failed;
            efficiency.reason = missing.reason;
        }
        for (TestResult* r : {&structure, &closest, &anyHit}) results.push_back(std::move(*r));
        if (scene->bruteForceSecondsPerRay > 0.0) results.push_back(std::move(efficiency));
    };
    return group;
}

}  // namespace rtlab::grader
