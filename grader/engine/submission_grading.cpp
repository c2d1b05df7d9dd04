#include "grader/engine/submission_grading.h"

#include "framework/core/error.h"
#include "grader/engine/assignment_registry.h"
#include "grader/engine/compile_sandbox.h"
#include "grader/engine/compiler_messages.h"
#include "grader/engine/pristine_stubs.h"
#include "grader/engine/worker_sources.h"
#include "grader/engine/submission_build.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// The assignments/ folders the chosen assignments' tests call; empty (all of them) when every
// assignment is graded.
std::vector<std::string> gradedFolders(const std::vector<std::string>& assignmentIds) {
    std::vector<std::string> folders;
    for (const std::string& id : assignmentIds)
        if (const Assignment* a = findAssignment(id))
            for (const std::string& folder : a->folders)
                if (std::find(folders.begin(), folders.end(), folder) == folders.end()) folders.push_back(folder);
    return folders;
}

}  // namespace

GradingReport gradeSubmission(const std::string& submissionDir, const SubmissionOptions& options) {
    auto start = std::chrono::steady_clock::now();
    GradingOptions g = options.grading;
    g.implementation = "submission " + submissionDir;
    fs::create_directories(options.workDir);
    // The grader's own stubs are read before the submission: a problem there (git, a new
    // assignment not committed) is the instructor's, so it stops grading with its one line
    // instead of failing the student's build test.
    const std::vector<std::string> folders = gradedFolders(g.assignments);
    std::map<std::string, std::string> stubs = pristineStubs(g.sourceDir, folders);
    TestResult buildTest = makeResult("build", "build");
    SubmissionBuild build;
    std::string unreadable;
    try {
        build = buildSubmission(submissionDir, g.sourceDir, stubs, options.toolchainPath, options.workDir + "/build", g.compile, folders);
    } catch (const Error& e) {
        unreadable = e.what();
    }
    if (!unreadable.empty()) {
        g.unavailableWorker = "not graded: the submission cannot be read (see the build test)";
        buildTest.reason = "the submission cannot be read: " + unreadable;
    } else if (build.succeeded) {
        g.workerPath = build.executable;
        if (!g.runEveryPhase) g.unstartedStubs = unstartedStubs(stubs, build.executable);
        buildTest.status = TestStatus::Passed;
        buildTest.fraction = 1.0;
        for (const std::string& file : build.fromSubmission) buildTest.details.push_back("from the submission: " + file);
        std::string compiled = "compiled " + std::to_string(build.sources - build.cached) + " of " + std::to_string(build.sources) + " .cpp files";
        if (build.cached > 0) compiled += "; the others were compiled before, byte for byte, with the same headers";
        buildTest.details.push_back(compiled);
        for (const std::string& line : build.slower) buildTest.details.push_back(line);
    } else {
        // Every test is still listed, failed, so the score is 0 of the assignments' points.
        g.unavailableWorker = "not graded: the submission does not compile (see the build test)";
        buildTest.reason = "the submission does not compile: " + firstError(build.log);
    }
    for (const std::string& line : splitLines(build.log, 60)) buildTest.details.push_back(line);

    GradingReport report = gradeWorker(g, {buildTest});
    // The compile sandbox a submission is built in, also when it could not be read.
    report.isolation += "; " + CompileSandbox::detect().description();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace rtlab::grader
