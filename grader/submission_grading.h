// Grading submissions from outside (docs/grading.md, "Grading a submission"): build a
// student's folder into its own rtlab, let that rtlab grade itself (its student code runs
// only in its sandboxed children) and read back its JSON report; a failed build is a failed
// "build" test with the compiler's messages. Also a whole folder of submissions in parallel,
// into a CSV.
#pragma once

#include "grader/grading_report.h"
#include "grader/grading_session.h"

#include <string>

namespace rtlab::grader {

struct SubmissionOptions {
    GradingOptions grading;  // seed, limits, assignments, source and models directories
    std::string toolchainPath;
    std::string workDir;  // a fresh directory for this submission
};

GradingReport gradeSubmission(const std::string& submissionDir, const SubmissionOptions& options);

// Grades every subdirectory of submissionsDir with `jobs` in parallel; writes one row per
// submission (name, score, max_score, build, then the score of every test) to csvPath and each
// submission's JSON report to reportsDir/<name>.json. Returns the number graded.
size_t gradeSubmissions(const std::string& submissionsDir, const SubmissionOptions& options, int jobs,
                        const std::string& csvPath, const std::string& reportsDir);

}  // namespace rtlab::grader
