#include "grader/engine/batch_grading.h"

#include "framework/core/error.h"
#include "grader/engine/capped_process.h"
#include "grader/engine/grades_csv.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/rubric.h"
#include "framework/core/untrusted_text.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// What one grading child left: its report, or why there is none (with the end of its log).
struct ChildOutcome {
    bool graded = false;
    GradingReport report;
    std::string reason;
    std::vector<std::string> log;
    double seconds = 0.0;
};

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

ChildOutcome runGradingChild(const BatchOptions& options, const std::string& folder, const fs::path& workDir) {
    ChildOutcome outcome;
    std::error_code ignored;
    fs::remove_all(workDir, ignored);
    fs::create_directories(workDir);
    if (fs::is_symlink(folder, ignored) && !fs::exists(folder, ignored)) {
        outcome.reason = "the folder is a symbolic link to a missing target (" + fs::read_symlink(folder, ignored).string() + ")";
        return outcome;
    }
    std::string json = (workDir / "report.json").string(), log = (workDir / "grade.log").string();
    std::vector<std::string> arguments = {options.executable, "grade", "--submission", folder, "--json", json, "--quiet",
                                          "--work", (workDir / "work").string()};
    arguments.insert(arguments.end(), options.gradeArguments.begin(), options.gradeArguments.end());
    CappedRun run = runCapped(arguments, log, options.secondsPerSubmission);
    outcome.seconds = run.seconds;
    if (run.succeeded()) {
        try {
            outcome.report = readJsonReport(json);
            outcome.graded = true;
            return outcome;
        } catch (const Error& e) {
            outcome.reason = std::string("its grading left no report: ") + e.what();
        }
    } else {
        outcome.reason = "its grading " + run.describe(options.secondsPerSubmission);
    }
    outcome.log = lines(tailOfFile(log, 30));
    if (!outcome.log.empty()) outcome.reason += ": " + outcome.log.back();
    return outcome;
}

// The tests the grader defines for the chosen assignments: those its grading of the pristine
// stubs (an empty submission) reports. Rows are scored over these names only.
std::vector<TestResult> definedTests(const BatchOptions& options) {
    fs::path empty = fs::path(options.workDir) / "pristine-stubs" / "submission";
    fs::create_directories(empty);
    ChildOutcome stubs = runGradingChild(options, empty.string(), fs::path(options.workDir) / "pristine-stubs" / "grading");
    if (!stubs.graded) throw Error("cannot grade the pristine stubs (an empty submission): " + stubs.reason);
    std::vector<TestResult> defined;
    for (const TestResult& t : stubs.report.tests) {
        TestResult d;
        d.assignment = t.assignment;
        d.name = t.name;
        defined.push_back(d);
    }
    return defined;
}

// The row of one submission: the grader's own tests, scored by the rubric from what the child
// reported; a submission whose grading failed gets every test failed, with the reason.
GradingReport submissionRow(const std::string& folder, const ChildOutcome& child, const std::vector<TestResult>& defined,
                            const Rubric& rubric) {
    // Everything else the child reported (seed, student output, the isolation in force) stays.
    GradingReport row = child.graded ? child.report : GradingReport{};
    row.implementation = "submission " + folder;
    row.seconds = child.seconds;
    if (child.graded) {
        row.tests = rubric.applyToDefined(defined, child.report.tests);
        return row;
    }
    TestResult build;
    build.assignment = "build";
    build.name = "build";
    build.reason = "not graded: " + child.reason;
    build.details = child.log;
    row.tests = rubric.applyToDefined(defined, {build}, build.reason);
    return row;
}

// Written beside its final name and renamed, so a batch killed half-way never leaves a
// truncated report that a re-run would take for a graded submission.
void writeReportAtomically(const GradingReport& report, const std::string& path) {
    std::string partial = path + ".partial";
    writeJsonReport(report, partial);
    fs::rename(partial, path);
}

std::string reportPath(const BatchOptions& options, const std::string& folder) {
    return (fs::path(options.reportsDir) / (fs::path(folder).filename().string() + ".json")).string();
}

// A folder whose grading could not even be set up (its work folder cannot be made, say) still
// gets its row.
ChildOutcome gradeFolder(const BatchOptions& options, const std::string& folder) {
    try {
        return runGradingChild(options, folder, fs::path(options.workDir) / "submissions" / fs::path(folder).filename());
    } catch (const std::exception& e) {
        ChildOutcome failed;
        failed.reason = std::string("its grading could not be started: ") + e.what();
        return failed;
    }
}

// Runs task(0..count-1) on `jobs` threads; the first exception a task throws is rethrown once
// all threads have ended.
void forEachInParallel(size_t count, int jobs, const std::function<void(size_t)>& task) {
    std::atomic<size_t> next{0};
    std::mutex mutex;
    std::exception_ptr failure;
    auto drain = [&] {
        for (size_t i; (i = next++) < count;) try {
                task(i);
            } catch (...) {
                std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
            }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < std::max(1, jobs); ++j) threads.emplace_back(drain);
    for (std::thread& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
}

std::string progressLine(const std::string& name, const GradingReport& row, const ChildOutcome& child) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, ": %.2f of %.2f points, %.0f s", row.score(), row.maxScore(), child.seconds);
    std::string line = escapeUntrusted(name, TextLayout::OneLine) + buffer;
    if (!child.graded) line += ", not graded: " + truncateUtf8(escapeUntrusted(child.reason, TextLayout::OneLine), 200);
    return line;
}

}  // namespace

Shard Shard::parse(const std::string& text) {
    Shard shard;
    size_t slash = text.find('/');
    try {
        size_t end = 0;
        if (slash == std::string::npos) throw std::invalid_argument("no slash");
        shard.index = std::stoi(text.substr(0, slash), &end);
        if (end != slash) throw std::invalid_argument("trailing characters");
        shard.count = std::stoi(text.substr(slash + 1), &end);
        if (end != text.size() - slash - 1) throw std::invalid_argument("trailing characters");
    } catch (const std::logic_error&) {
        throw Error("--shard " + text + ": expected K/N, e.g. 1/4");
    }
    if (shard.count < 1 || shard.index < 1 || shard.index > shard.count)
        throw Error("--shard " + text + ": K must be 1..N and N at least 1");
    return shard;
}

std::vector<std::string> submissionFolders(const std::string& submissionsDir) {
    std::error_code error;
    fs::directory_iterator it(submissionsDir, error);
    if (error) throw Error(submissionsDir + ": cannot read the submissions folder (" + error.message() + ")");
    std::vector<std::string> folders;
    for (const fs::directory_entry& entry : it) {
        std::error_code ignored;
        bool dangling = entry.is_symlink(ignored) && !fs::exists(entry.path(), ignored);
        if (entry.is_directory(ignored) || dangling) folders.push_back(entry.path().string());
    }
    std::sort(folders.begin(), folders.end());
    return folders;
}

BatchSummary gradeBatch(const BatchOptions& options) {
    std::vector<std::string> folders = submissionFolders(options.submissionsDir), todo;
    BatchSummary summary;
    for (size_t i = 0; i < folders.size(); ++i) {
        if (!options.shard.holds(i)) continue;
        std::string report = reportPath(options, folders[i]);
        summary.reportPaths.push_back(report);
        if (!options.force && fs::exists(report)) {
            ++summary.skipped;
            continue;
        }
        todo.push_back(folders[i]);
    }
    fs::create_directories(options.reportsDir);
    if (!todo.empty()) {
        std::vector<TestResult> defined = definedTests(options);
        std::mutex printing;
        forEachInParallel(todo.size(), options.jobs, [&](size_t i) {
            std::string name = fs::path(todo[i]).filename().string();
            ChildOutcome child = gradeFolder(options, todo[i]);
            GradingReport row = submissionRow(todo[i], child, defined, options.rubric);
            writeReportAtomically(row, reportPath(options, todo[i]));
            std::lock_guard lock(printing);
            ++(child.graded ? summary.graded : summary.notGraded);
            std::cerr << progressLine(name, row, child) << "\n";
        });
    }
    if (!options.csvPath.empty()) writeGradesCsv(summary.reportPaths, options.csvPath, options.rubric.precision());
    return summary;
}

}  // namespace rtlab::grader
