// The course's grade sheet: one CSV row per per-student JSON report (docs/grading.md, "Grading
// a batch"). `rtlab grade merge` and the batch itself write it with the same code, so a CSV
// merged from the shards of a fan-out equals the one a single batch writes.
#pragma once

#include <string>
#include <vector>

namespace rtlab::grader {

// The *.json reports in these folders, sorted by file name; throws rtlab::Error naming a
// folder that cannot be read and a file name that two folders both hold.
std::vector<std::string> reportsInFolders(const std::vector<std::string>& folders);

// Columns: submission (the report's file name without .json), score, max_score, reason (why
// the submission was not graded in full, when it was not), then every test any report has,
// in first-seen order. Numbers have `precision` decimals. Written next to csvPath first and
// renamed, so a malformed report (rtlab::Error naming it) leaves an existing CSV untouched.
void writeGradesCsv(const std::vector<std::string>& reportPaths, const std::string& csvPath, int precision);

}  // namespace rtlab::grader
