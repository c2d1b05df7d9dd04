// The viewer pages tests/viewer/browser_test.py opens that `rtlab view` cannot make, written
// through the API the grader's report calls (viewer/case_view.h):
//   dda/        a3's DDA on a flat 8 x 6 grid: the exact walk against a student walk that steps
//               the wrong way from its fourth cell on, so the page has expected-only, student-only
//               and shared cells, each drawn where browser_test.py projects it;
//   hostile/    what a hostile worker could return: markup and script in every string, a trace
//               with NaN, infinite and out-of-range numbers, a structure whose links run wild;
//   report/     an HTML grading report with one failing test whose every student-controlled
//               string (reason, details, printed output, its viewer case's words) carries markup
//               and script, linked to its viewer as `rtlab grade --html` links it;
//   passing/    a report whose tests all pass: no viewer folder.
// Usage: viewer_test_cases OUTPUT_DIR (prints the cells of the DDA case as JSON on stdout).
#include "framework/accel/bvh_accelerator.h"
#include "framework/core/error.h"
#include "framework/scene/gltf_loader.h"
#include "grader/a3_grid/grid_oracle.h"
#include "grader/engine/grading_report.h"
#include "viewer/report_viewers.h"
#include "viewer/case_view.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace {

namespace fs = std::filesystem;
using namespace rtlab;

const char* const kHostile =
    "</script><script>window.__pwned=1</script><img src=x onerror=\"window.__pwned=2\"><b id=injected>bold</b>";

void writeDda(const fs::path& dir) {
    viewer::CaseView view;
    view.title = "a3/dda/cell-order: the expected walk against a wrong one";
    view.notes = {"expected cells only: blue; the student's only: red; both: purple"};
    viewer::DdaCells dda;
    dda.bounds = Bounds3f(Vec3(0.0f), Vec3(8.0f, 6.0f, 1.0f));
    dda.resolution = {8, 6, 1};
    Ray ray{Vec3(-1.0f, 0.7f, 0.5f), Vec3(1.0f, 0.53f, 0.0f)};
    auto walk = grader::exactCellWalk(grader::frameOf(dda.bounds, dda.resolution), ray, 1.0f, 10.0f);
    if (!walk) throw Error("the DDA case's ray is ambiguous");
    dda.expected = *walk;
    // The wrong walk: from the fourth cell on, one row lower.
    dda.student = dda.expected;
    for (size_t k = 3; k < dda.student.size(); ++k) dda.student[k][1] = std::max(0, dda.student[k][1] - 1);
    viewer::RayCase& c = view.rays.emplace_back();
    c.ray = ray;
    c.label = "ray 0";
    view.dda = dda;
    viewer::writeCaseViewer(dir, view);
    std::printf("{\"bounds\": [0, 0, 0, 8, 6, 1], \"expected\": [");
    for (size_t k = 0; k < dda.expected.size(); ++k)
        std::printf("%s[%d, %d, %d]", k ? ", " : "", dda.expected[k][0], dda.expected[k][1], dda.expected[k][2]);
    std::printf("], \"student\": [");
    for (size_t k = 0; k < dda.student.size(); ++k)
        std::printf("%s[%d, %d, %d]", k ? ", " : "", dda.student[k][0], dda.student[k][1], dda.student[k][2]);
    std::printf("]}\n");
}

void writeHostile(const fs::path& dir, const fs::path& sourceDir) {
    Scene scene = loadGltf((sourceDir / "scenes" / "cornell-box.gltf").string());
    viewer::CaseView view;
    view.title = kHostile;
    view.notes = {kHostile, "javascript:alert(1)", std::string("\x1b]0;title\x07 and \xc3\x28 invalid UTF-8")};
    view.scene = &scene;
    view.acceleratorName = "bvh";
    view.draw = drawBvh;
    // A structure with a cycle, a link out of range and a leaf whose list runs past the end.
    StructureView s;
    float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    s.nodes.push_back({Bounds3f(Vec3(-1.0f), Vec3(1.0f, 2.0f, 1.0f)), 0, 3, 0, 0});
    s.nodes.push_back({Bounds3f(Vec3(nan), Vec3(inf)), 0, 0, 0, 1u << 31});
    s.nodes.push_back({Bounds3f(Vec3(-1.0f), Vec3(0.0f)), 0, 0, 0, 2});
    s.children = {0, 1, 2, 1u << 30};
    s.nodes[0].firstChild = 0;
    s.nodes[0].childCount = 4;
    s.primIndices = {4, 0xffffffffu};
    view.structure = s;
    viewer::RayCase& c = view.rays.emplace_back();
    c.ray = Ray{Vec3(0.0f, 1.0f, 3.0f), Vec3(0.0f, 0.0f, -1.0f)};
    c.label = kHostile;
    c.expectedSource = kHostile;
    c.student = viewer::RayAnswer::closest(0xfffffffeu, nan);
    c.expected = viewer::RayAnswer::closest(4, inf);
    TraversalTrace t;
    t.addBox(Bounds3f(Vec3(nan), Vec3(inf)), true, nan, inf);
    t.add(TraceOp{TraceOpKind::LeafEntry, 0, 0, 0xfffffffeu, nan, -inf});
    t.add(TraceOp{TraceOpKind::PrimitiveTest, 1, 0, 1u << 30, inf, nan});
    t.add(TraceOp{TraceOpKind::MailboxRepeat, 0, 0, 0xffffffffu, 0.0f, 0.0f});
    t.add(TraceOp{TraceOpKind::CellStep});
    t.add(TraceOp{TraceOpKind::PrimitiveTest, 1, 0, 4, 2.5f, inf});
    t.dropped = 1u << 20;
    c.studentTrace = t;
    c.expectedTrace = TraversalTrace{};
    viewer::writeCaseViewer(dir, view);
}

// Through the same calls as `rtlab grade --html` (cli/grade_command.cpp).
void writeReport(const fs::path& dir, const grader::GradingReport& report) {
    fs::create_directories(dir);
    grader::writeHtmlReport(report, dir.string(), viewer::writeReportViewers(report, dir));
}

void writeHostileReport(const fs::path& dir, const fs::path& sourceDir) {
    const std::string hostile = std::string(kHostile) + "</textarea><a href=\"javascript:window.__pwned=3\">javascript:alert(1)</a>";
    grader::GradingReport report;
    report.implementation = hostile;
    report.studentOutput = hostile + "\n<script>window.__pwned=4</script>";
    grader::TestResult& t = report.tests.emplace_back();
    t.assignment = "a1";
    t.name = "a1/bvh/closest-hits";
    t.reason = hostile;
    t.details = {hostile, "ray 0 " + hostile};
    grader::FailedCase failed;
    failed.title = hostile;
    failed.notes = {hostile, "javascript:alert(1)"};
    failed.scene = std::make_shared<Scene>(loadGltf((sourceDir / "scenes" / "cornell-box.gltf").string()));
    grader::CaseRay& r = failed.rays.emplace_back();
    r.ray = Ray{Vec3(0.0f, 1.0f, 3.0f), Vec3(0.0f, 0.0f, -1.0f)};
    r.label = hostile;
    r.student = grader::CaseAnswer::closest(0xfffffffeu, std::numeric_limits<float>::quiet_NaN());
    r.expected = grader::CaseAnswer::closest(4, 2.5f);
    TraversalTrace trace;
    trace.add(TraceOp{TraceOpKind::PrimitiveTest, 1, 0, 1u << 30, std::numeric_limits<float>::infinity(), 0.0f});
    r.studentTrace = trace;
    grader::addFailedCase(t, std::move(failed));
    writeReport(dir, report);
}

void writePassingReport(const fs::path& dir) {
    grader::GradingReport report;
    report.implementation = "solutions/";
    grader::TestResult& t = report.tests.emplace_back();
    t.assignment = "a1";
    t.name = "a1/bvh/closest-hits";
    t.status = grader::TestStatus::Passed;
    t.fraction = 1.0;
    writeReport(dir, report);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: viewer_test_cases OUTPUT_DIR SOURCE_DIR\n");
        return 2;
    }
    try {
        fs::path out(argv[1]);
        fs::create_directories(out);
        writeDda(out / "dda");
        writeHostile(out / "hostile", argv[2]);
        writeHostileReport(out / "report", argv[2]);
        writePassingReport(out / "passing");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "viewer_test_cases: %s\n", e.what());
        return 1;
    }
    return 0;
}
