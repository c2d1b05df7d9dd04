// The outcome of one grading run and the report formats (docs/grading.md, "Reports"):
// a terminal table, JSON, Gradescope's results.json, JUnit XML and an HTML page with images.
#pragma once

#include "grader/engine/test_result.h"

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace rtlab::grader {

struct GradingReport {
    std::string implementation;  // what was graded: "assignments/ (linked into rtlab)", a submission folder
    uint64_t seed = 0;
    double seconds = 0.0;
    std::vector<TestResult> tests;
    std::string studentOutput;  // what student code printed (first few KiB)
    std::string isolation;      // how student code was isolated, as the sandbox and the build report it

    double score() const;
    double maxScore() const;
};

// The text a report shows for a test: its reason and detail lines.
std::string testOutput(const TestResult& test);

// The report with every text field passed through escapeUntrusted (framework/core/untrusted_text.h):
// names, reasons and detail lines as one line each, student output with its line breaks.
// Scores, images' file paths and timings are unchanged. Every writer below starts with it.
GradingReport displaySafe(const GradingReport& report);

// The table: one row per test, its reason wrapped at word boundaries under the reason column;
// with verbose, every detail line of the tests that are not passing (each failing case: the
// box or triangle, the ray, what was expected and what came back) under their row; last, the
// "Next:" line naming the first test that is not passing, its stub and docs section.
void printTerminalReport(const GradingReport& report, std::ostream& out, bool colour, bool verbose = false);

// The terminal report's last line: "Next: TEST — STUB — DOCS" for the first test that is not
// passing (the stub a not-started reason names, else the rubric guide's), or that all pass.
std::string nextStepLine(const GradingReport& report);

// Splits text into lines of at most width displayed characters (UTF-8 code points; East Asian
// wide characters count two, combining marks none), breaking at spaces only; a word longer
// than width stands alone on its line, whole.
std::vector<std::string> wrapWords(const std::string& text, size_t width);
size_t displayWidth(const std::string& text);
// The JSON report: score, max_score, seed, execution_time, implementation and
// tests[{name, assignment, status, score, max_score, visibility, output, details, images}].
void writeJsonReport(const GradingReport& report, const std::string& path);
// Reads a JSON report back (the --submission mode reads the one its grading child wrote).
GradingReport readJsonReport(const std::string& path);
// Gradescope's results.json (autograder specification: score, execution_time, output,
// stdout_visibility, tests[{name, number, score, max_score, status, output, visibility, tags}]).
void writeGradescopeResults(const GradingReport& report, const std::string& path);
void writeJunitReport(const GradingReport& report, const std::string& path);
// A link from a failing test to the viewer page of one of its cases (the viewer writes the pages,
// viewer/report_viewers.h): its words and its address relative to the report's index.html.
struct ReportLink {
    std::string label;
    std::string href;
};
using ReportLinks = std::map<std::string, std::vector<ReportLink>>;  // by test name

// DIR/index.html with every test's messages; images are copied into DIR/images. Each test
// named in viewerLinks gets an "open in viewer" link per entry.
void writeHtmlReport(const GradingReport& report, const std::string& directory, const ReportLinks& viewerLinks = {});

}  // namespace rtlab::grader
