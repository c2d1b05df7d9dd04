// Grading submissions from outside (docs/grading.md, "Grading a submission"): build a
// student's folder into a worker of its own in the compile sandbox, then grade that worker
// here; a failed build is a failed "build" test with the compiler's messages, and every other
// test is listed failed, so the score is 0 of the full points. A folder of submissions:
// grader/engine/batch_grading.h.
#pragma once

#include "grader/engine/grading_report.h"
#include "grader/engine/grading_session.h"

#include <string>

namespace rtlab::grader {

struct SubmissionOptions {
    GradingOptions grading;  // seed, limits, assignments, source and models directories
    std::string toolchainPath;
    std::string workDir;  // a fresh directory for this submission
};

GradingReport gradeSubmission(const std::string& submissionDir, const SubmissionOptions& options);

}  // namespace rtlab::grader
