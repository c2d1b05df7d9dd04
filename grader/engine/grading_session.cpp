#include "grader/engine/grading_session.h"

#include "framework/core/error.h"
#include "grader/engine/assignment_registry.h"
#include "grader/engine/failed_case_traces.h"
#include "grader/engine/grading_rubric.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <unistd.h>

namespace rtlab::grader {

void mergeSameNamed(std::vector<TestResult>& results) {
    std::vector<TestResult> merged;
    std::map<std::string, size_t> position;
    std::map<std::string, size_t> parts;
    std::map<std::string, std::string> notStarted;  // test -> the reason of its first part not started
    for (TestResult& r : results) {
        if (r.status == TestStatus::NotStarted) notStarted.try_emplace(r.name, r.reason);
        auto [it, inserted] = position.try_emplace(r.name, merged.size());
        if (inserted) {
            parts[r.name] = 1;
            merged.push_back(std::move(r));
            continue;
        }
        TestResult& m = merged[it->second];
        size_t n = parts[r.name]++;
        m.fraction = (m.fraction * double(n) + r.fraction) / double(n + 1);
        m.seconds += r.seconds;
        m.details.insert(m.details.end(), r.details.begin(), r.details.end());
        m.images.insert(m.images.end(), r.images.begin(), r.images.end());
        for (FailedCase& c : r.failedCases) addFailedCase(m, std::move(c));
        if (m.status == r.status && m.status != TestStatus::Failed) continue;  // all passed, or none started
        // Mixed: a failure's reason says more than "not started", which says more than nothing.
        if (m.status != TestStatus::Failed && (r.status == TestStatus::Failed || m.status == TestStatus::Passed)) m.reason = r.reason;
        m.status = TestStatus::Failed;
    }
    // A test that meets a stub not started anywhere is not started: scenes that happen not to
    // call the stub (a leaf from the framework's rules) earn nothing on their own.
    for (TestResult& m : merged)
        if (m.status != TestStatus::NotStarted && notStarted.count(m.name)) {
            m.status = TestStatus::NotStarted;
            m.fraction = 0.0;
            m.reason = notStarted[m.name];
        }
    results = std::move(merged);
}

namespace {

SandboxRun unavailableWorkerRun(size_t phases, const std::string& reason) {
    SandboxRun run;
    run.phases.assign(phases, PhaseOutcome{PhaseStatus::Failed, {}, reason, 0.0, 0.0});
    return run;
}

bool matchesAny(const std::vector<std::string>& patterns, const std::string& name) {
    return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& p) { return globMatches(p, name); });
}

// The tests a group defines, each failed: its scoring on phases that all failed, without a
// worker. Only the grader's own data goes in, so the names and their number are the grader's;
// a group lists every test even when no phase ran (a submission that does not compile).
std::vector<TestResult> definedTests(const TestGroup& group) {
    std::vector<TestResult> defined;
    group.score(unavailableWorkerRun(group.phases.size(), "not run"), defined);
    return defined;
}

bool reportsWantedTest(const std::vector<TestResult>& defined, const std::vector<std::string>& patterns) {
    return std::any_of(defined.begin(), defined.end(), [&](const TestResult& r) { return matchesAny(patterns, r.name); });
}

// The group's verdicts on what the worker sent, for exactly the tests it defines: whatever the
// worker's data made the scoring do (throw on a malformed record, skip or add a test), every
// defined test is reported once under its own name, one the scoring did not reach as failed.
void scoreDefinedTests(const TestGroup& group, const SandboxRun& run, const std::vector<TestResult>& defined,
                       std::vector<TestResult>& into) {
    std::vector<TestResult> reported;
    std::string broken;
    try {
        group.score(run, reported);
    } catch (const std::exception& e) {
        broken = std::string("sent malformed results: ") + e.what();
    }
    for (const TestResult& test : defined) {
        auto it = std::find_if(reported.begin(), reported.end(), [&](const TestResult& r) { return r.name == test.name; });
        if (it != reported.end()) {
            into.push_back(std::move(*it));
            continue;
        }
        TestResult missing = test;
        missing.status = TestStatus::Failed;
        missing.fraction = 0.0;
        missing.reason = broken.empty() ? "no verdict: the worker's results left this test unscored" : broken;
        into.push_back(std::move(missing));
    }
}

// Whether every test a group defines already has a part that was not started. Running the
// group cannot change those verdicts (mergeSameNamed reports a test not started when any part
// of it is), so an assignment left untouched costs one group per test, not one per scene.
bool allNotStarted(const std::vector<TestResult>& defined, const std::set<std::string>& notStarted) {
    return !defined.empty() && std::all_of(defined.begin(), defined.end(), [&](const TestResult& r) { return notStarted.count(r.name) > 0; });
}

}  // namespace

GradingReport gradeWorker(const GradingOptions& options, std::vector<TestResult> leading) {
    auto start = std::chrono::steady_clock::now();
    GradingContext context;
    context.seed = options.seed;
    context.sourceDir = options.sourceDir;
    context.modelsDir = options.modelsDir;
    context.workDir = options.workDir;
    context.structureKey = (uint64_t(std::random_device{}()) << 32) ^ std::random_device{}();
    std::string referenceDir = options.sourceDir + "/grader/reference";
    context.reference = options.writeReference ? ReferenceData::forWriting(referenceDir) : ReferenceData::load(referenceDir);
    Rubric rubric = loadGradingRubric(options.sourceDir, options.rubricPath);

    auto wanted = [&](const std::string& a) {
        return options.assignments.empty() || std::find(options.assignments.begin(), options.assignments.end(), a) != options.assignments.end();
    };
    std::vector<TestGroup> groups;
    auto add = [&](std::vector<TestGroup> more) {
        for (TestGroup& g : more)
            if (wanted(g.assignment)) groups.push_back(std::move(g));
    };
    for (const Assignment& assignment : assignments())
        if (wanted(assignment.id)) add(assignment.groups(context));
    std::vector<std::vector<TestResult>> defined;
    for (const TestGroup& g : groups) defined.push_back(definedTests(g));
    if (!options.tests.empty()) {
        for (size_t i = groups.size(); i-- > 0;)
            if (!reportsWantedTest(defined[i], options.tests)) {
                groups.erase(groups.begin() + std::ptrdiff_t(i));
                defined.erase(defined.begin() + std::ptrdiff_t(i));
            }
        if (groups.empty()) throw Error("--test: no test of the graded assignments matches the patterns given");
    }

    GradingReport report;
    report.implementation = options.implementation;
    report.seed = options.seed;
    report.isolation = workerIsolation();
    WorkerSpec worker{options.workerPath, options.limits};
    StubVerdicts known(options.unstartedStubs);
    bool terminal = options.progress && isatty(STDERR_FILENO);
    std::set<std::string> notStarted;
    // While a group runs, the next one's worker starts (sandbox.h, StartedWorker).
    auto startAhead = [&](size_t i) -> std::optional<StartedWorker> {
        if (i >= groups.size() || !options.unavailableWorker.empty() || allNotStarted(defined[i], notStarted)) return std::nullopt;
        std::vector<size_t> order = phasesToRun(groups[i].phases, &known, worker.limits);
        if (order.empty()) return std::nullopt;
        return std::optional<StartedWorker>(std::in_place, worker, groups[i].phases, std::move(order));
    };
    std::optional<StartedWorker> next = startAhead(0);
    for (size_t i = 0; i < groups.size(); ++i) {
        const TestGroup& group = groups[i];
        std::optional<StartedWorker> current = std::exchange(next, std::nullopt);
        if (allNotStarted(defined[i], notStarted)) continue;
        if (terminal) std::cerr << "\r\033[K[" << i + 1 << "/" << groups.size() << "] " << group.title << std::flush;
        next = startAhead(i + 1);
        SandboxRun run;
        if (!options.unavailableWorker.empty()) run = unavailableWorkerRun(group.phases.size(), options.unavailableWorker);
        else if (!group.phases.empty()) run = runSandboxed(worker, group.phases, &known, std::move(current));
        size_t first = report.tests.size();
        scoreDefinedTests(group, run, defined[i], report.tests);
        for (size_t k = first; k < report.tests.size(); ++k)
            if (report.tests[k].status == TestStatus::NotStarted) notStarted.insert(report.tests[k].name);
        if (report.studentOutput.size() < 4096) report.studentOutput += run.output.substr(0, 4096 - report.studentOutput.size());
    }
    if (terminal) std::cerr << "\r\033[K" << std::flush;
    for (TestResult& test : report.tests)
        if (test.needsFollowedStructure) requireFollowedStructure(context, test);
    if (!options.tests.empty())
        std::erase_if(report.tests, [&](const TestResult& r) { return !matchesAny(options.tests, r.name); });
    mergeSameNamed(report.tests);
    // The failing cases' walks for the report's viewer, once every verdict is in.
    if (options.traceFailures && options.unavailableWorker.empty()) recordStudentTraces(report.tests, worker);
    report.tests.insert(report.tests.begin(), leading.begin(), leading.end());
    rubric.apply(report.tests);
    if (options.writeReference) context.reference.save();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace rtlab::grader
