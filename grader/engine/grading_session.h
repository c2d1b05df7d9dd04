// One grading run (docs/grading.md): builds the test groups of the chosen assignments, runs
// each in sandboxed workers (options.workerPath, which holds the code to grade; this process
// links none), scores them in this process and applies the rubric.
#pragma once

#include "grader/engine/grading_report.h"
#include "grader/engine/sandbox.h"
#include "grader/engine/submission_build.h"
#include "grader/engine/test_group.h"

#include <set>
#include <string>
#include <vector>

namespace rtlab::grader {

struct GradingOptions {
    uint64_t seed = kDefaultSeed;
    std::string sourceDir;   // repository root (scenes/, grader/rubric.json, grader/reference/)
    std::string modelsDir;   // bunny.gltf
    std::string workDir;     // renders and heat maps
    std::string rubricPath;  // empty: grader/rubric.json with every assignment's part (grading_rubric.h)
    std::vector<std::string> assignments;  // empty: every registered one (assignment_registry.h)
    std::vector<std::string> tests;        // glob patterns of test names (rubric.h's globMatches); empty: all
    std::string workerPath;  // the worker executable holding the code to grade (grader/worker/)
    std::string unavailableWorker;  // when set, no worker runs and every phase fails with this reason
    SandboxLimits limits;
    // The stubs (StubTable::name) whose file the worker holds exactly as committed
    // (worker_sources.h): their phases are reported not started without running.
    std::set<std::string> unstartedStubs;
    bool runEveryPhase = false;  // a submission's unstartedStubs stay empty: every phase runs
    CompileLimits compile;   // for a submission's build
    bool writeReference = false;  // record SAH costs and work per ray into grader/reference/
    bool progress = true;         // progress lines on stderr when it is a terminal
    // Trace the student's walk of the failing cases' rays for the HTML report's viewer: one
    // more sandboxed run, after the verdicts, that nothing else reads.
    bool traceFailures = false;
    std::string implementation;   // what is graded, for the reports
};

// `leading` are tests graded before this run (a submission's build), reported first; the
// rubric is loaded and applied once, to them and to every test of the run.
GradingReport gradeWorker(const GradingOptions& options, std::vector<TestResult> leading = {});

// Merges results that share a name (one per scene) into one test: passed when all passed,
// not started when any part is, otherwise failed with the first failure's reason; the
// fraction is the mean, so each scene carries an equal share of the points.
void mergeSameNamed(std::vector<TestResult>& results);

}  // namespace rtlab::grader
