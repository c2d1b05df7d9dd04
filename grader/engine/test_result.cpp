#include "grader/engine/test_result.h"

namespace rtlab::grader {

const char* testStatusName(TestStatus status) {
    switch (status) {
    case TestStatus::Passed: return "passed";
    case TestStatus::Failed: return "failed";
    case TestStatus::NotStarted: return "not started";
    }
    return "?";
}

void addFailedCase(TestResult& result, FailedCase failed) {
    if (result.failedCases.size() >= kViewerCasesPerTest) return;
    if (failed.rays.size() > kViewerRaysPerCase) failed.rays.resize(kViewerRaysPerCase);
    if (failed.cells) {
        if (failed.cells->expected.size() > kViewerCellsPerWalk) failed.cells->expected.resize(kViewerCellsPerWalk);
        if (failed.cells->student.size() > kViewerCellsPerWalk) failed.cells->student.resize(kViewerCellsPerWalk);
    }
    result.failedCases.push_back(std::move(failed));
}

void markPassed(TestResult& result, const std::string& detail) {
    result.status = TestStatus::Passed;
    result.fraction = 1.0;
    result.reason.clear();
    if (!detail.empty()) result.details.push_back(detail);
}

void markFailed(TestResult& result, const std::string& reason) {
    result.status = TestStatus::Failed;
    result.fraction = 0.0;
    result.reason = reason;
}

void CaseTally::record(bool passed, const std::string& detail, const std::string& reason) {
    ++total_;
    if (passed) {
        ++passed_;
        return;
    }
    result_.details.push_back(detail);
    if (first_.empty()) first_ = reason;
}

void setFromCounts(TestResult& result, size_t passed, size_t total, const std::string& firstFailure) {
    result.fraction = total == 0 ? 0.0 : double(passed) / double(total);
    if (total > 0 && passed == total) {
        result.status = TestStatus::Passed;
        result.reason.clear();
        return;
    }
    result.status = TestStatus::Failed;
    result.reason = std::to_string(total - passed) + " of " + std::to_string(total) + " cases wrong; first: " + firstFailure;
}

}  // namespace rtlab::grader
