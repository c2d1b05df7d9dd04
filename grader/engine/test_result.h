// The verdict on one graded test, as every report prints it (docs/grading.md, "Reading the
// report"). Scores are filled in from the rubric after the test ran.
#pragma once

#include "grader/engine/failed_case.h"

#include <string>
#include <vector>

namespace rtlab::grader {

enum class TestStatus { Passed, Failed, NotStarted };

const char* testStatusName(TestStatus status);  // "passed", "failed", "not started"

// An image a report shows next to others (render, reference, heat map).
struct ReportImage {
    std::string label;
    std::string path;  // absolute
};

struct TestResult {
    std::string assignment;  // "a0"
    std::string name;        // "a0/slab/face-planes": the key the rubric matches
    TestStatus status = TestStatus::Failed;
    double fraction = 0.0;             // share of the points earned; 1 when passed
    std::string reason;                // one line; empty when passed
    std::vector<std::string> details;  // further lines: failing rays, costs, per-scene results
    std::vector<ReportImage> images;
    // The first few failing cases as data for the viewer (failed_case.h); empty when passed.
    std::vector<FailedCase> failedCases;
    double seconds = 0.0;
    // Credited only when its assignment's traversal follows the structures it is given
    // (GradingContext::unfollowedStructure): a test a private structure would pass. The session
    // checks once every group has run, so a scene graded before the one that found it out is
    // held to it too.
    bool needsFollowedStructure = false;

    // From the rubric.
    double maxScore = 0.0;
    double score = 0.0;
    std::string visibility = "visible";
    std::string stub;  // the file to work on, from the rubric's guides (may be empty)
    std::string docs;  // the docs section about it, "docs/a0-intersect.md#slab-test"
};

// The file name ending of the heat maps image tests write; the HTML report puts the colour
// legend under them (the suffix survives a report's JSON round trip, a flag would not).
inline constexpr const char* kHeatMapFileSuffix = "-heatmap.png";

// Keeps a failing case for the report's viewer links unless the test has kViewerCasesPerTest;
// its rays are cut to kViewerRaysPerCase and its cells to kViewerCellsPerWalk.
void addFailedCase(TestResult& result, FailedCase failed);

// Passed when every case passed; otherwise failed with partial credit passed/total.
void setFromCounts(TestResult& result, size_t passed, size_t total, const std::string& firstFailure);

// Set a result's verdict: passed with one detail line (none when empty), or failed with a reason.
void markPassed(TestResult& result, const std::string& detail);
void markFailed(TestResult& result, const std::string& reason);

// One case's verdict as the tally records it: the detail line (--verbose, the HTML report) may
// say more than the reason line, which names the first failing case.
struct CaseLine {
    bool passed;
    std::string detail, reason;
};

// The line of a case named `name` (its id, or its id with its input spelled out): "<name>: <problem>".
inline CaseLine caseLine(const std::string& name, const std::string& problem) {
    return {problem.empty(), name + ": " + problem, name + ": " + problem};
}

// The verdicts of a truth table, case by case: counts the passes, keeps one detail line per
// failing case ("id: problem"), and finish() sets the result from the counts, the first failure
// as its reason.
class CaseTally {
public:
    explicit CaseTally(TestResult& result) : result_(result) {}
    // An empty problem means the case passed.
    void record(const std::string& id, const std::string& problem) { record(caseLine(id, problem)); }
    // A case whose detail line says more than its reason (e.g. the shape it was tested on).
    void record(bool passed, const std::string& detail, const std::string& reason);
    void record(const CaseLine& line) { record(line.passed, line.detail, line.reason); }
    void finish() { setFromCounts(result_, passed_, total_, first_); }

private:
    TestResult& result_;
    size_t passed_ = 0, total_ = 0;
    std::string first_;
};

}  // namespace rtlab::grader
