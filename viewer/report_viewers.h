// The HTML report's "open in viewer" links (docs/viewer.md#from-the-report): every failing
// test's recorded cases (grader/engine/failed_case.h, at most kViewerCasesPerTest each) written
// as viewer folders under REPORT/viewer/, and the links the report shows for them. The grader
// records the cases as plain data and never includes this file; the command line calls it
// before it writes the report.
#pragma once

#include "grader/engine/grading_report.h"
#include "viewer/case_view.h"

#include <filesystem>

namespace rtlab::viewer {

// The folder under the report's that holds its viewers.
inline constexpr const char* kReportViewerFolder = "viewer";
// At most this many viewer pages a report, in the report's order of tests: each page inlines
// three.js (about 0.9 MB a page), so a submission that fails everything still gets a report of
// about 30 MB, not hundreds. The cases past it are listed without a page.
inline constexpr size_t kViewerPagesPerReport = 30;

// What one failing case shows: the student's answer against the expected one, the student's
// structure, the DDA's cells, the failed image at its worst pixel. Points into failed.scene.
CaseView caseViewOf(const grader::FailedCase& failed);

// Writes REPORT_DIR/viewer/<test>-<k>/ for every failing case of every failed test and returns
// the links by test name (addresses relative to REPORT_DIR/index.html). REPORT_DIR/viewer is
// replaced whole when it holds only viewers (a report written before); a passing report leaves
// none behind. A case whose viewer cannot be written gets a link without an address, its words
// saying why.
grader::ReportLinks writeReportViewers(const grader::GradingReport& report, const std::filesystem::path& reportDir);

}  // namespace rtlab::viewer
