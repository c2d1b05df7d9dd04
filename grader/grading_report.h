// The outcome of one grading run and the report formats (docs/grading.md, "Reports"):
// a terminal table, JSON, Gradescope's results.json, JUnit XML and an HTML page with images.
#pragma once

#include "grader/test_result.h"

#include <cstdint>
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

// The report with every text field passed through escapeUntrusted (grader/untrusted_text.h):
// names, reasons and detail lines as one line each, student output with its line breaks.
// Scores, images' file paths and timings are unchanged. Every writer below starts with it.
GradingReport displaySafe(const GradingReport& report);

void printTerminalReport(const GradingReport& report, std::ostream& out, bool colour);
// The JSON report: score, max_score, seed, execution_time, implementation and
// tests[{name, assignment, status, score, max_score, visibility, output, details, images}].
void writeJsonReport(const GradingReport& report, const std::string& path);
// Reads a JSON report back (the --submission mode reads the one its grading child wrote).
GradingReport readJsonReport(const std::string& path);
// Gradescope's results.json (autograder specification: score, execution_time, output,
// stdout_visibility, tests[{name, number, score, max_score, status, output, visibility, tags}]).
void writeGradescopeResults(const GradingReport& report, const std::string& path);
void writeJunitReport(const GradingReport& report, const std::string& path);
// DIR/index.html with every test's messages; images are copied into DIR/images.
void writeHtmlReport(const GradingReport& report, const std::string& directory);

}  // namespace rtlab::grader
