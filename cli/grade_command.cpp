// rtlab grade (docs/grading.md): grades the implementation linked into this executable
// (rtlab: assignments/, rtlab-solution: solutions/), a student's submission folder, or a
// folder of submissions (or one shard of it), and writes the reports asked for;
// `rtlab grade merge` joins per-student reports into the CSV.
#include "cli/commands.h"
#include "cli/this_build.h"
#include "framework/core/error.h"
#include "grader/engine/assignment_registry.h"
#include "grader/engine/batch_grading.h"
#include "grader/engine/grades_csv.h"
#include "grader/engine/grading_session.h"
#include "grader/engine/grading_rubric.h"
#include "grader/engine/pristine_stubs.h"
#include "grader/engine/submission_grading.h"
#include "grader/engine/worker_sources.h"
#include "viewer/report_viewers.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace rtlab::cli {
namespace {

namespace fs = std::filesystem;

struct GradeFlags {
    grader::GradingOptions grading;
    std::string json, gradescope, junit, html, submission, submissions, csv, reports, shard;
    std::string label;
    int jobs = 2;
    double secondsPerSubmission = 900;
    double failUnder = -1;  // percent; negative: not asked for
    bool force = false;
    bool quiet = false;
    bool verbose = false;
};

struct MergeFlags {
    std::vector<std::string> reportFolders;
    std::string csv, rubric;
};

fs::path executableDir() { return fs::read_symlink("/proc/self/exe").parent_path(); }

// --fail-under P: a CI job fails when the score is below P % of the maximum.
void checkFailUnder(const grader::GradingReport& report, double percent) {
    if (percent < 0) return;
    double achieved = report.maxScore() > 0 ? 100.0 * report.score() / report.maxScore() : 0.0;
    if (achieved + 1e-9 >= percent) return;
    char message[160];
    std::snprintf(message, sizeof message, "score %.2f of %.2f points (%.1f %%) is below --fail-under %g %%", report.score(),
                  report.maxScore(), achieved, percent);
    throw Error(message);
}

// The flags every grading child of a batch gets, so it grades exactly as this run would.
std::vector<std::string> childGradeArguments(const grader::GradingOptions& g) {
    std::vector<std::string> arguments = {"--root", g.sourceDir, "--models", g.modelsDir, "--seed", std::to_string(g.seed),
                                          "--time-limit", std::to_string(g.limits.wallSeconds),
                                          "--memory-limit", std::to_string(g.limits.memoryMiB),
                                          "--compile-time-limit", std::to_string(g.compile.wallSeconds)};
    if (!g.rubricPath.empty()) arguments.insert(arguments.end(), {"--rubric", g.rubricPath});
    for (const std::string& a : g.assignments) arguments.insert(arguments.end(), {"--assignment", a});
    for (const std::string& t : g.tests) arguments.insert(arguments.end(), {"--test", t});
    return arguments;
}

void gradeFolderOfSubmissions(const GradeFlags& flags) {
    const grader::GradingOptions& g = flags.grading;
    grader::BatchOptions batch;
    batch.submissionsDir = flags.submissions;
    if (!flags.shard.empty()) batch.shard = grader::Shard::parse(flags.shard);
    // A shard of a fan-out writes reports only, unless a CSV is named; `grade merge` joins them.
    // The default lands in out/, which git ignores, wherever the command runs from.
    std::string csv = flags.csv.empty() ? "out/grades.csv" : flags.csv;
    if (flags.csv.empty() && flags.shard.empty() && fs::exists(csv)) throw Error(csv + " exists; choose the output with --csv FILE");
    if (!flags.csv.empty() || flags.shard.empty()) batch.csvPath = csv;
    if (fs::path(csv).has_parent_path()) fs::create_directories(fs::path(csv).parent_path());
    batch.reportsDir = flags.reports.empty() ? (fs::path(csv).parent_path() / (fs::path(csv).stem().string() + "-reports")).string()
                                             : flags.reports;
    batch.workDir = g.workDir;
    batch.rubric = grader::loadGradingRubric(g.sourceDir, g.rubricPath);
    batch.executable = fs::read_symlink("/proc/self/exe").string();
    batch.gradeArguments = childGradeArguments(g);
    batch.jobs = flags.jobs;
    batch.force = flags.force;
    batch.secondsPerSubmission = flags.secondsPerSubmission;
    grader::BatchSummary summary = grader::gradeBatch(batch);
    std::cout << "graded " << summary.graded << " submissions, " << summary.notGraded << " not graded (their rows say why), "
              << summary.skipped << " skipped (already graded; --force grades them again); reports in " << batch.reportsDir;
    if (!batch.csvPath.empty()) std::cout << ", CSV " << batch.csvPath;
    std::cout << "\n";
}

void merge(const MergeFlags& flags) {
    std::vector<std::string> reports = grader::reportsInFolders(flags.reportFolders);
    if (reports.empty()) throw Error(flags.reportFolders.front() + ": no JSON reports to merge");
    grader::writeGradesCsv(reports, flags.csv, grader::loadGradingRubric(repositoryDir(), flags.rubric).precision());
    std::cout << "merged " << reports.size() << " reports into " << flags.csv << "\n";
}

void writeReports(const grader::GradingReport& report, const GradeFlags& flags) {
    if (!flags.quiet) grader::printTerminalReport(report, std::cout, isatty(STDOUT_FILENO), flags.verbose);
    if (!flags.json.empty()) grader::writeJsonReport(report, flags.json);
    if (!flags.gradescope.empty()) grader::writeGradescopeResults(report, flags.gradescope);
    if (!flags.junit.empty()) grader::writeJunitReport(report, flags.junit);
    if (!flags.html.empty()) {
        // The failing cases' viewers first, so the report links to folders that exist.
        fs::create_directories(flags.html);
        auto start = std::chrono::steady_clock::now();
        grader::ReportLinks links = viewer::writeReportViewers(report, flags.html);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        grader::writeHtmlReport(report, flags.html, links);
        size_t pages = 0;
        for (const auto& [test, list] : links) pages += list.size();
        if (!flags.quiet) {
            std::cout << "HTML report: " << (fs::absolute(flags.html) / "index.html").string();
            if (pages > 0) {
                char written[96];
                std::snprintf(written, sizeof written, " (%zu failing cases in the viewer, written in %.2f s)", pages, seconds);
                std::cout << written;
            }
            std::cout << "\n";
        }
    }
}

void grade(GradeFlags& flags) {
    grader::GradingOptions& g = flags.grading;
    if (g.sourceDir.empty()) g.sourceDir = repositoryDir();
    g.traceFailures = !flags.html.empty();
    if (g.modelsDir.empty()) g.modelsDir = (executableDir() / "models").string();
    if (!fs::is_directory(g.sourceDir + "/grader"))
        throw Error("--root " + g.sourceDir + " is not the rtlab repository (no grader/ folder)");
    for (const std::string& a : g.assignments)
        if (!grader::findAssignment(a)) throw Error("--assignment " + a + " is not an assignment (valid: " + grader::assignmentIds() + ")");
    // Renders and heat maps go to a temporary folder unless --work names one; the HTML report
    // keeps copies.
    bool temporaryWork = g.workDir.empty();
    if (temporaryWork) g.workDir = (fs::temp_directory_path() / ("rtlab-grade-" + std::to_string(getpid()))).string();
    struct RemoveOnExit {
        std::string path;
        ~RemoveOnExit() {
            std::error_code ignored;
            if (!path.empty()) fs::remove_all(path, ignored);
        }
    } cleanup{temporaryWork ? g.workDir : ""};
    g.progress = !flags.quiet;

    if (!flags.submission.empty() || !flags.submissions.empty()) {
        if (g.writeReference) throw Error("--write-reference grades the linked implementation only, not --submission");
        grader::SubmissionOptions options;
        options.grading = g;
        options.toolchainPath = (executableDir() / "grader" / "submission-toolchain.json").string();
        options.workDir = g.workDir;
        if (!flags.submissions.empty()) {
            if (flags.failUnder >= 0) throw Error("--fail-under applies to one grading, not to --submissions");
            gradeFolderOfSubmissions(flags);
            return;
        }
        grader::GradingReport report = grader::gradeSubmission(fs::absolute(flags.submission).string(), options);
        writeReports(report, flags);
        checkFailUnder(report, flags.failUnder);
        return;
    }
    if (g.workerPath.empty()) g.workerPath = (executableDir() / "rtlab-worker").string();
    if (!fs::is_regular_file(g.workerPath)) throw Error("--worker " + g.workerPath + ": no such worker executable (make build builds it)");
    g.implementation = flags.label.empty() ? g.workerPath + " (the implementation it links)" : flags.label;
    // A test whose stub the worker holds as committed is reported not started without running
    // (worker_sources.h). Without git's HEAD to compare with, every test runs: slower, same verdicts.
    try {
        if (!g.runEveryPhase) g.unstartedStubs = grader::unstartedStubs(grader::committedStubs(g.sourceDir), g.workerPath);
    } catch (const Error&) {
        g.unstartedStubs.clear();
    }
    grader::GradingReport report = grader::gradeWorker(g);
    writeReports(report, flags);
    checkFailUnder(report, flags.failUnder);
}

void addMergeCommand(CLI::App& grade) {
    auto flags = std::make_shared<MergeFlags>();
    CLI::App* cmd = grade.add_subcommand("merge", "Join per-student JSON reports (of a batch or of its shards) into one CSV");
    cmd->add_option("REPORTS_DIR", flags->reportFolders, "Folders with the <submission>.json reports")
        ->required()->check(CLI::ExistingDirectory);
    cmd->add_option("--csv", flags->csv, "The CSV to write")->required();
    cmd->add_option("--rubric", flags->rubric, "Rubric whose precision the numbers get (default grader/rubric.json)")
        ->check(CLI::ExistingFile);
    cmd->callback([flags] { merge(*flags); });
}

}  // namespace

void addGradeCommand(CLI::App& app) {
    auto flags = std::make_shared<GradeFlags>();
    CLI::App* cmd = app.add_subcommand("grade", "Grade the assignments: unit truth tables, hit sets against the oracle, "
                                                "BVH structure and SAH cost, images against POV-Ray (docs/grading.md)");
    cmd->add_option("--seed", flags->grading.seed, "Seed of the random ray sets and property tests")->capture_default_str();
    cmd->add_option("--assignment", flags->grading.assignments, "Grade only these assignments (" + grader::assignmentIds() + "); repeatable");
    cmd->add_option("--test", flags->grading.tests,
                    "Grade only the tests whose names match this pattern ('*' matches anything: a3/dda/*, */efficiency); repeatable");
    cmd->add_option("--json", flags->json, "Write the JSON report to FILE");
    cmd->add_option("--gradescope", flags->gradescope, "Write Gradescope's results.json to FILE");
    cmd->add_option("--junit", flags->junit, "Write a JUnit XML report to FILE");
    cmd->add_option("--html", flags->html, "Write an HTML report (index.html and images) into DIR");
    cmd->add_option("--submission", flags->submission, "Build and grade the student folder DIR instead of the linked implementation")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--submissions", flags->submissions, "Grade every subfolder of DIR into a CSV")->check(CLI::ExistingDirectory);
    cmd->add_option("--csv", flags->csv, "CSV file for --submissions (default out/grades.csv, never overwritten unless named)");
    cmd->add_option("--reports", flags->reports, "Folder for the per-student JSON reports of --submissions (default: <csv>-reports)");
    cmd->add_option("--shard", flags->shard, "With --submissions: grade only every N-th folder, starting at the K-th (K/N, by name)");
    cmd->add_flag("--force", flags->force, "With --submissions: grade again the folders whose report exists");
    cmd->add_option("--submission-time-limit", flags->secondsPerSubmission,
                    "With --submissions: wall-clock seconds one submission's grading may take (then it is killed)")
        ->capture_default_str()->check(CLI::Range(1.0, 86400.0));
    cmd->add_option("--fail-under", flags->failUnder, "Exit non-zero when the score is below P percent of the maximum")
        ->check(CLI::Range(0.0, 100.0));
    cmd->add_option("--jobs", flags->jobs, "Submissions graded in parallel")->capture_default_str()->check(CLI::Range(1, 64));
    cmd->add_option("--time-limit", flags->grading.limits.wallSeconds, "Seconds of CPU time per test phase (at most 4 times that of wall-clock time)")
        ->capture_default_str()->check(CLI::Range(0.1, 600.0));
    cmd->add_option("--compile-time-limit", flags->grading.compile.wallSeconds,
                    "Wall-clock seconds a submission's build may take (then the compiler is stopped)")
        ->capture_default_str()->check(CLI::Range(1.0, 3600.0));
    cmd->add_option("--memory-limit", flags->grading.limits.memoryMiB, "MiB of memory student code may allocate")
        ->capture_default_str()->check(CLI::Range(16, 65536));
    cmd->add_option("--rubric", flags->grading.rubricPath, "Rubric file (default grader/rubric.json)")->check(CLI::ExistingFile);
    cmd->add_option("--root", flags->grading.sourceDir, "The rtlab repository (scenes, rubric, reference data)");
    cmd->add_option("--models", flags->grading.modelsDir, "Folder with bunny.gltf (default: models/ next to the executable)");
    cmd->add_option("--work", flags->grading.workDir, "Folder for renders and heat maps (default: a temporary folder)");
    cmd->add_option("--label", flags->label, "What is graded, as the reports name it");
    cmd->add_option("--worker", flags->grading.workerPath,
                    "The worker executable holding the code to grade (default: rtlab-worker next to rtlab-grader; "
                    "rtlab grade and rtlab-solution grade name theirs)");
    cmd->add_flag("--write-reference", flags->grading.writeReference,
                  "Record SAH costs and work per ray into grader/reference/ (run with rtlab-solution)");
    cmd->add_flag("--run-every-phase", flags->grading.runEveryPhase,
                  "Run the tests of stubs the code holds exactly as committed too, instead of reporting them "
                  "not started without running (the same verdicts, slower)");
    cmd->add_flag("--quiet", flags->quiet, "No table and no progress on the terminal");
    cmd->add_flag("--verbose", flags->verbose,
                  "Under each test that is not passing, every failing case: the box or triangle, the ray, "
                  "what was expected and what came back");
    addMergeCommand(*cmd);
    cmd->callback([flags, cmd] {
        if (cmd->got_subcommand("merge")) return;  // CLI11 runs this after merge's own callback
        if (!flags->submission.empty() && !flags->submissions.empty()) throw Error("use either --submission or --submissions");
        if (flags->submissions.empty() && (!flags->shard.empty() || flags->force || !flags->reports.empty()))
            throw Error("--shard, --force and --reports go with --submissions");
        grade(*flags);
    });
}

}  // namespace rtlab::cli
