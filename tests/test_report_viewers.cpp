// The HTML report's "open in viewer" links (docs/viewer.md#from-the-report): a failing test's
// cases become viewer folders under REPORT/viewer with relative links, at most
// kViewerCasesPerTest a test and kViewerPagesPerReport a report, each capped; a passing report
// writes no viewer data and removes the viewers an earlier report left; the heat map's legend
// is printed once.
#include "framework/scene/gltf_loader.h"
#include "framework/verification/image_compare.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/grading_session.h"
#include "tests/output_dirs.h"
#include "viewer/report_viewers.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rtlab;
using namespace rtlab::grader;
namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

// A failing closest-hit case on the Cornell box: the student's miss against the oracle's hit.
FailedCase wrongHit(const std::shared_ptr<const Scene>& scene, int k) {
    FailedCase failed;
    failed.title = "[cornell-box] closest-hits: ray " + std::to_string(k);
    failed.notes = {"expected a hit at t=2.5 on prim {4}, got a miss"};
    failed.scene = scene;
    CaseRay& r = failed.rays.emplace_back();
    r.ray = Ray{Vec3(0.0f, 1.0f, 3.0f), Vec3(0.0f, 0.0f, -1.0f)};
    r.label = "ray " + std::to_string(k);
    r.student = CaseAnswer::closest(kNoHit, kInfinity);
    r.expected = CaseAnswer::closest(4, 2.5f);
    return failed;
}

void writeReport(const GradingReport& report, const fs::path& dir) {
    fs::create_directories(dir);
    writeHtmlReport(report, dir.string(), viewer::writeReportViewers(report, dir));
}

}  // namespace

TEST_CASE("addFailedCase keeps the first few cases of a test, each capped") {
    TestResult result;
    for (int k = 0; k < 5; ++k) {
        FailedCase failed;
        failed.rays.resize(20);
        failed.cells = CaseCells{};
        failed.cells->student.resize(kViewerCellsPerWalk + 10);
        addFailedCase(result, std::move(failed));
    }
    REQUIRE(result.failedCases.size() == kViewerCasesPerTest);
    CHECK(result.failedCases[0].rays.size() == kViewerRaysPerCase);
    CHECK(result.failedCases[0].cells->student.size() == kViewerCellsPerWalk);

    // A test over several scenes is merged into one: still at most kViewerCasesPerTest cases.
    std::vector<TestResult> parts(2, result);
    parts[0].name = parts[1].name = "a1/median/closest-hits";
    mergeSameNamed(parts);
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].failedCases.size() == kViewerCasesPerTest);
}

TEST_CASE("a failing report links each case to its viewer; a passing one writes no viewer data") {
    auto scene = std::make_shared<const Scene>(loadGltf(RTLAB_SOURCE_DIR "/scenes/cornell-box.gltf"));
    GradingReport report;
    report.implementation = "test";
    TestResult& failing = report.tests.emplace_back();
    failing.name = "a1/median/closest-hits";
    failing.status = TestStatus::Failed;
    failing.reason = "1 of 1000 rays wrong";
    for (int k = 0; k < 2; ++k) addFailedCase(failing, wrongHit(scene, k));
    TestResult& passing = report.tests.emplace_back();
    passing.name = "a1/median/structure";
    passing.status = TestStatus::Passed;
    passing.failedCases.push_back(wrongHit(scene, 9));  // never shown: the test passed

    fs::path dir = test::outputDir("report_viewers") / "failing";
    fs::remove_all(dir);
    writeReport(report, dir);
    std::string page = readFile(dir / "index.html");
    CHECK(count(page, ">open in viewer</a>") == 2);
    CHECK(page.find("href=\"viewer/a1-median-closest-hits-1/index.html\"") != std::string::npos);
    CHECK(page.find("href=\"viewer/a1-median-closest-hits-2/index.html\"") != std::string::npos);
    CHECK(fs::is_regular_file(dir / "viewer" / "a1-median-closest-hits-1" / "index.html"));
    CHECK(fs::is_regular_file(dir / "viewer" / "a1-median-closest-hits-1" / viewer::kViewerMarker));
    CHECK_FALSE(fs::exists(dir / "viewer" / "a1-median-structure-1"));

    // The same folder graded again, all passing: the old viewers go, no new ones come.
    report.tests[0].status = TestStatus::Passed;
    writeReport(report, dir);
    CHECK_FALSE(fs::exists(dir / "viewer"));
    CHECK(readFile(dir / "index.html").find("open in viewer") == std::string::npos);

    // A viewer/ folder that holds something else is not removed, and not overwritten.
    fs::create_directories(dir / "viewer" / "notes");
    report.tests[0].status = TestStatus::Failed;
    writeReport(report, dir);
    CHECK(fs::is_directory(dir / "viewer" / "notes"));
}

TEST_CASE("a report writes at most kViewerPagesPerReport viewer pages; the cases past them are listed without a link") {
    auto scene = std::make_shared<const Scene>(loadGltf(RTLAB_SOURCE_DIR "/scenes/cornell-box.gltf"));
    GradingReport report;
    for (size_t i = 0; i * kViewerCasesPerTest <= viewer::kViewerPagesPerReport; ++i) {
        TestResult& t = report.tests.emplace_back();
        t.name = "a1/test-" + std::to_string(i);
        for (size_t k = 0; k < kViewerCasesPerTest; ++k) addFailedCase(t, wrongHit(scene, int(k)));
    }
    fs::path dir = test::outputDir("report_viewers") / "many";
    fs::remove_all(dir);
    writeReport(report, dir);
    std::string page = readFile(dir / "index.html");
    CHECK(count(page, ">open in viewer</a>") == viewer::kViewerPagesPerReport);
    CHECK(count(page, "viewer pages went to the tests above") == kViewerCasesPerTest);
    CHECK(size_t(std::distance(fs::directory_iterator(dir / "viewer"), fs::directory_iterator())) == viewer::kViewerPagesPerReport);
}

TEST_CASE("a DDA case shows both walks; an image case its worst pixel") {
    auto scene = std::make_shared<const Scene>(loadGltf(RTLAB_SOURCE_DIR "/scenes/cornell-box.gltf"));
    FailedCase dda;
    dda.title = "a3/dda/cell-order: grid 0";
    dda.rays.emplace_back().ray = Ray{Vec3(-1.0f, 0.5f, 0.5f), Vec3(1.0f, 0.2f, 0.0f)};
    dda.cells = CaseCells{Bounds3f(Vec3(0.0f), Vec3(8.0f)), {8, 8, 8}, {{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {0, 1, 0}}};
    viewer::CaseView view = viewer::caseViewOf(dda);
    REQUIRE(view.dda);
    CHECK(view.dda->expected.size() == 2);
    CHECK(view.dda->student[1] == GridCell{0, 1, 0});

    FailedCase image;
    image.scene = scene;
    image.image = CaseImage{"", "", "", 0, 32, 24, std::array<int, 2>{5, 7}, "3 % of pixels off"};
    view = viewer::caseViewOf(image);
    REQUIRE(view.images);
    CHECK(view.images->selectedPixel == std::array<int, 2>{5, 7});
    REQUIRE(view.rays.size() == 1);  // the worst pixel's camera ray
    CHECK(view.rays[0].expected.kind == viewer::RayAnswer::Kind::Closest);
}

TEST_CASE("the heat map's legend is printed once") {
    GradingReport report;
    TestResult& t = report.tests.emplace_back();
    t.name = "a0/images/cornell-box";
    fs::path dir = test::outputDir("report_viewers") / "legend";
    fs::path heat = dir / ("cornell-box" + std::string(kHeatMapFileSuffix));
    fs::create_directories(dir);
    std::ofstream(heat) << "not an image: the report only copies it";
    t.images = {{"difference in 16-bit codes", heat.string()}};
    writeHtmlReport(report, (dir / "html").string());
    std::string page = readFile(dir / "html" / "index.html");
    for (const HeatMapBand& band : errorHeatMapBands()) CHECK(count(page, band.meaning) == 1);
}
