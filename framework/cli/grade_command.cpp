// rtlab grade (docs/grading.md): grades the implementation linked into this executable
// (rtlab: assignments/, rtlab-solution: solutions/), a student's submission folder, or a
// folder of submissions, and writes the reports asked for.
#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "grader/grading_session.h"
#include "grader/submission_grading.h"

#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace rtlab::cli {
namespace {

namespace fs = std::filesystem;

struct GradeFlags {
    grader::GradingOptions grading;
    std::string json, gradescope, junit, html, submission, submissions, csv;
    std::string label;
    int jobs = 2;
    bool quiet = false;
};

fs::path executableDir() { return fs::read_symlink("/proc/self/exe").parent_path(); }

void writeReports(const grader::GradingReport& report, const GradeFlags& flags) {
    if (!flags.quiet) grader::printTerminalReport(report, std::cout, isatty(STDOUT_FILENO));
    if (!flags.json.empty()) grader::writeJsonReport(report, flags.json);
    if (!flags.gradescope.empty()) grader::writeGradescopeResults(report, flags.gradescope);
    if (!flags.junit.empty()) grader::writeJunitReport(report, flags.junit);
    if (!flags.html.empty()) {
        grader::writeHtmlReport(report, flags.html);
        if (!flags.quiet) std::cout << "HTML report: " << (fs::absolute(flags.html) / "index.html").string() << "\n";
    }
}

void grade(GradeFlags& flags) {
    grader::GradingOptions& g = flags.grading;
    if (g.sourceDir.empty()) g.sourceDir = RTLAB_GRADER_SOURCE_DIR;
    if (g.modelsDir.empty()) g.modelsDir = (executableDir() / "models").string();
    if (!fs::is_directory(g.sourceDir + "/grader"))
        throw Error("--root " + g.sourceDir + " is not the rtlab repository (no grader/ folder)");
    for (const std::string& a : g.assignments)
        if (a != "a0" && a != "a1" && a != "a2") throw Error("--assignment " + a + " is not an assignment (valid: a0, a1, a2)");
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
            std::string csv = flags.csv.empty() ? "grades.csv" : flags.csv;
            if (flags.csv.empty() && fs::exists(csv)) throw Error(csv + " exists; choose the output with --csv FILE");
            std::string reports = (fs::path(csv).parent_path() / (fs::path(csv).stem().string() + "-reports")).string();
            size_t n = grader::gradeSubmissions(flags.submissions, options, flags.jobs, csv, reports);
            std::cout << "graded " << n << " submissions into " << csv << " (reports in " << reports << ")\n";
            return;
        }
        writeReports(grader::gradeSubmission(fs::absolute(flags.submission).string(), options), flags);
        return;
    }
    g.implementation = flags.label.empty() ? executableDir().string() + "/" + fs::read_symlink("/proc/self/exe").filename().string() +
                                                 " (the implementation it links)"
                                           : flags.label;
    writeReports(grader::gradeLinkedImplementation(g), flags);
}

}  // namespace

void addGradeCommand(CLI::App& app) {
    auto flags = std::make_shared<GradeFlags>();
    CLI::App* cmd = app.add_subcommand("grade", "Grade the assignments: unit truth tables, hit sets against the oracle, "
                                                "BVH structure and SAH cost, images against POV-Ray (docs/grading.md)");
    cmd->add_option("--seed", flags->grading.seed, "Seed of the random ray sets and property tests")->capture_default_str();
    cmd->add_option("--assignment", flags->grading.assignments, "Grade only these assignments (a0, a1, a2); repeatable");
    cmd->add_option("--json", flags->json, "Write the JSON report to FILE");
    cmd->add_option("--gradescope", flags->gradescope, "Write Gradescope's results.json to FILE");
    cmd->add_option("--junit", flags->junit, "Write a JUnit XML report to FILE");
    cmd->add_option("--html", flags->html, "Write an HTML report (index.html and images) into DIR");
    cmd->add_option("--submission", flags->submission, "Build and grade the student folder DIR instead of the linked implementation")
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--submissions", flags->submissions, "Grade every subfolder of DIR into a CSV")->check(CLI::ExistingDirectory);
    cmd->add_option("--csv", flags->csv, "CSV file for --submissions (default grades.csv, never overwritten unless named)");
    cmd->add_option("--jobs", flags->jobs, "Submissions graded in parallel")->capture_default_str()->check(CLI::Range(1, 64));
    cmd->add_option("--time-limit", flags->grading.limits.wallSeconds, "Wall-clock seconds per test phase")
        ->capture_default_str()->check(CLI::Range(0.1, 600.0));
    cmd->add_option("--memory-limit", flags->grading.limits.memoryMiB, "MiB of memory student code may allocate")
        ->capture_default_str()->check(CLI::Range(16, 65536));
    cmd->add_option("--rubric", flags->grading.rubricPath, "Rubric file (default grader/rubric.json)")->check(CLI::ExistingFile);
    cmd->add_option("--root", flags->grading.sourceDir, "The rtlab repository (scenes, rubric, reference data)");
    cmd->add_option("--models", flags->grading.modelsDir, "Folder with bunny.gltf (default: models/ next to the executable)");
    cmd->add_option("--work", flags->grading.workDir, "Folder for renders and heat maps (default: a temporary folder)");
    cmd->add_option("--label", flags->label, "What is graded, as the reports name it");
    cmd->add_flag("--write-reference", flags->grading.writeReference,
                  "Record SAH costs and work per ray into grader/reference/ (run with rtlab-solution)");
    cmd->add_flag("--quiet", flags->quiet, "No table and no progress on the terminal");
    cmd->callback([flags] {
        if (!flags->submission.empty() && !flags->submissions.empty()) throw Error("use either --submission or --submissions");
        grade(*flags);
    });
}

}  // namespace rtlab::cli
