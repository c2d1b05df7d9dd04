// What a student reads and runs (issue 12): the terminal table wraps reasons at words and ends
// with the next step, --verbose lists every failing case, the HTML report shows a reason once
// and a heat-map legend, the heat map quantises to 16-bit codes, render writes a viewable PNG
// at the references' size and falls back from an a2 stub, and bad input gets one line that
// names the file.
#include "cli/render_accelerator.h"
#include "framework/core/error.h"
#include "framework/core/ray_file.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/scene/gltf_loader.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/grading_rubric.h"
#include "tests/cli_runner.h"
#include "tests/output_dirs.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

using namespace rtlab;
using namespace rtlab::grader;
namespace fs = std::filesystem;

namespace {

fs::path outputDir() { return test::outputDir("student_feedback"); }

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

Rubric shippedRubric() { return loadGradingRubric(RTLAB_SOURCE_DIR, ""); }

TestResult result(const std::string& name, TestStatus status, const std::string& reason, std::vector<std::string> details = {}) {
    TestResult t;
    t.assignment = name.substr(0, 2);
    t.name = name;
    t.status = status;
    t.fraction = status == TestStatus::Passed ? 1.0 : 0.0;
    t.reason = reason;
    t.details = std::move(details);
    return t;
}

// A long reason of words, one of them with multi-byte characters.
const std::string kLongReason =
    "3 of 12 cases wrong; first: BOX-01-x-lower o=(-2, 0.5, 0.5) d=(1, 0, 0): expected hit, got miss; "
    "the r\xc3\xa9sum\xc3\xa9 of \xe2\x82\xac-signs and \xe5\xb9\x85\xe5\xb9\x85 wide characters must not be cut in any word "
    "whatever the column the wrap falls on, so this sentence goes on a little longer than one row";

GradingReport sampleReport() {
    GradingReport report;
    report.implementation = "assignments/";
    report.tests = {result("a0/slab/face-planes", TestStatus::Passed, ""),
                    result("a0/slab/flat-boxes", TestStatus::Failed, kLongReason,
                           {"BOX-02 box (0, 0, 5)-(1, 1, 5), ray o=(0.5, 0.5, 0) d=(0, 0, 1): expected hit, got miss",
                            "BOX-03 box (0, 0, 0)-(0, 1, 1), ray o=(-1, 0.5, 0.5) d=(1, 0, 0): expected tEnter 1, got 2"}),
                    result("a0/triangle/boundary-t", TestStatus::NotStarted,
                           "not started: a0 intersectTriangle (assignments/a0_intersect/ray_triangle.cpp) throws NotImplemented")};
    shippedRubric().apply(report.tests);
    return report;
}

}  // namespace

TEST_CASE("wrapWords: lines of at most the width in displayed characters, broken at spaces only") {
    CHECK(displayWidth("abc") == 3);
    CHECK(displayWidth("r\xc3\xa9sum\xc3\xa9") == 6);          // two-byte characters count one
    CHECK(displayWidth("\xe2\x82\xac") == 1);                  // a three-byte one too
    CHECK(displayWidth("\xe5\xb9\x85\xe5\xb9\x85") == 4);      // East Asian wide: two columns each
    for (size_t width : {10, 17, 31, 80}) {
        CAPTURE(width);
        std::vector<std::string> lines = wrapWords(kLongReason, width);
        REQUIRE(lines.size() > 1);
        std::string joined;
        for (const std::string& line : lines) {
            // A word longer than the width stands alone; every other line fits.
            if (line.find(' ') != std::string::npos) CHECK(displayWidth(line) <= width);
            CHECK(line.front() != ' ');
            CHECK(line.back() != ' ');
            joined += (joined.empty() ? "" : " ") + line;
        }
        CHECK(joined == kLongReason);  // nothing cut, nothing lost
    }
    CHECK(wrapWords("", 10) == std::vector<std::string>{""});
    CHECK(wrapWords("averyveryverylongword x", 5) == std::vector<std::string>{"averyveryverylongword", "x"});
}

TEST_CASE("terminal report: reasons wrap under the reason column, --verbose lists every failing case, Next: names the step") {
    GradingReport report = sampleReport();
    std::ostringstream plain, verbose;
    printTerminalReport(report, plain, false);
    printTerminalReport(report, verbose, false, true);

    std::vector<std::string> lines = linesOf(plain.str());
    size_t row = 0;
    while (row < lines.size() && lines[row].rfind("a0/slab/flat-boxes", 0) != 0) ++row;
    REQUIRE(row < lines.size());
    size_t column = lines[row].find("3 of 12 cases wrong");
    REQUIRE(column != std::string::npos);
    // The continuation rows start with spaces up to the reason column, then a word.
    std::string rejoined = lines[row].substr(column);
    size_t k = row + 1;
    for (; k < lines.size() && lines[k].rfind(std::string(column, ' '), 0) == 0 && lines[k].size() > column; ++k) {
        CHECK(lines[k][column] != ' ');
        rejoined += " " + lines[k].substr(column);
    }
    CHECK(k > row + 1);
    CHECK(rejoined == kLongReason);
    CHECK(plain.str().find("...") == std::string::npos);  // not truncated

    // Details only with --verbose, and only for the tests that are not passing.
    CHECK(plain.str().find("BOX-02 box (0, 0, 5)-(1, 1, 5)") == std::string::npos);
    CHECK(verbose.str().find("- BOX-02 box (0, 0, 5)-(1, 1, 5), ray o=(0.5, 0.5, 0) d=(0, 0, 1): expected hit, got miss") !=
          std::string::npos);
    CHECK(verbose.str().find("- BOX-03 box") != std::string::npos);

    // The first test that is not passing, the stub and the docs section from the rubric's guides.
    CHECK(lines.back() ==
          "Next: a0/slab/flat-boxes \u2014 assignments/a0_intersect/ray_box.cpp \u2014 docs/a0-intersect.md#slab-test");
}

TEST_CASE("Next: a not-started test names the stub that threw; a report that passes says so") {
    GradingReport report = sampleReport();
    report.tests.erase(report.tests.begin() + 1);
    CHECK(nextStepLine(report) ==
          "Next: a0/triangle/boundary-t \u2014 assignments/a0_intersect/ray_triangle.cpp \u2014 docs/a0-intersect.md#watertight-triangles");
    report.tests.pop_back();
    CHECK(nextStepLine(report) == "Next: nothing, every test passes");

    // Every test the shipped rubric can score has a guide whose stub and docs page exist.
    std::vector<TestResult> names;
    for (const char* name : {"a0/sphere/cases", "a1/splits/median", "a1/median/structure", "a1/middle/any-hits", "a1/median/closest-hits",
                             "a1/images/cornell-box", "a2/splits/sweep", "a2/buckets-12/sah-cost", "a2/sweep-all-axes/closest-hits"})
        names.push_back(result(name, TestStatus::Failed, "x"));
    shippedRubric().apply(names);
    for (const TestResult& t : names) {
        CAPTURE(t.name);
        CHECK(fs::exists(fs::path(RTLAB_SOURCE_DIR) / t.stub));
        std::string page = t.docs.substr(0, t.docs.find('#'));
        CHECK(fs::exists(fs::path(RTLAB_SOURCE_DIR) / page));
    }
}

TEST_CASE("HTML report: each reason once, and the heat map's legend as colour swatches") {
    GradingReport report = sampleReport();
    fs::path heat = outputDir() / ("cornell-box" + std::string(kHeatMapFileSuffix));
    writeImage(heat.string(), Image(4, 3, 3));
    report.tests[1].images = {{"difference", fs::absolute(heat).string()}};
    fs::path dir = outputDir() / "html";
    writeHtmlReport(report, dir.string());
    std::string page = readFile(dir / "index.html");
    CHECK(count(page, "3 of 12 cases wrong") == 1);
    CHECK(count(page, "intersectTriangle") == 1);
    CHECK(page.find("BOX-02 box") != std::string::npos);  // the details are still there
    for (const HeatMapBand& band : errorHeatMapBands()) CHECK(page.find(band.meaning) != std::string::npos);
    CHECK(page.find("class=\"swatch\"><span style=\"background:#1a59ff\"") != std::string::npos);  // blue
}

TEST_CASE("heat map: both images are quantised to 16-bit codes first, so differences below a code are grey") {
    Image reference(8, 2, 3), render(8, 2, 3);
    for (int x = 0; x < 8; ++x)
        for (int c = 0; c < 3; ++c) {
            float code = 1000.0f + 7.0f * x;
            reference.at(x, 0, c) = reference.at(x, 1, c) = code / 65535.0f;
            // Row 0: a float render within a third of a code; row 1: one code off.
            render.at(x, 0, c) = (code + 0.3f * (c - 1)) / 65535.0f;
            render.at(x, 1, c) = (code + 1.0f) / 65535.0f;
        }
    fs::path heat = outputDir() / "quantised-heat.png";
    writeErrorHeatMap(render, reference, heat.string());
    Image map = readImage(heat.string());
    for (int x = 0; x < 8; ++x) {
        Vec3 equal = map.rgb(x, 0), one = map.rgb(x, 1);
        CHECK(equal.r == equal.g);  // grey
        CHECK(equal.g == equal.b);
        CHECK(one.b > 0.9f);  // blue: 1 code
        CHECK(one.r < 0.2f);
    }
    CHECK(errorHeatMapLegend().find("grey = equal in 16-bit codes") == 0);
}

TEST_CASE("rtlab render: an 8-bit sRGB PNG at the references' size by default, 16-bit linear with --linear16") {
    const std::string scene = std::string(RTLAB_SOURCE_DIR) + "/scenes/cornell-box.gltf";
    fs::path viewing = outputDir() / "view.png", linear = outputDir() / "linear.png";
    REQUIRE(test::runCliStatus({"render", scene, "-o", viewing.string(), "--threads", "2"}) == 0);
    REQUIRE(test::runCliStatus({"render", scene, "-o", linear.string(), "--linear16", "--threads", "2"}) == 0);
    auto format = [](const fs::path& path) {
        auto input = OIIO::ImageInput::open(path.string());
        REQUIRE(input);
        return std::make_pair(input->spec().format, std::make_pair(input->spec().width, input->spec().height));
    };
    CHECK(format(viewing).first == OIIO::TypeDesc::UINT8);
    CHECK(format(linear).first == OIIO::TypeDesc::UINT16);
    CHECK(format(viewing).second == std::make_pair(320, 240));
    CHECK(format(linear).second == std::make_pair(320, 240));

    // The 16-bit one compares with the committed reference as it is; the 8-bit one is refused
    // with the flag to use, and so is a render of another size, with the size to use.
    const std::string reference = std::string(RTLAB_SOURCE_DIR) + "/scenes/refs/cornell-box.png";
    CHECK(test::runCliStatus({"compare", linear.string(), reference}) == 0);
    CHECK_THROWS_WITH_AS(compareImages(viewing.string(), reference), doctest::Contains("--linear16"), Error);
    CHECK_THROWS_WITH_AS(compareImages(viewing.string(), reference), doctest::Contains("view.png"), Error);
    CHECK(test::runCliStatus({"compare", viewing.string(), reference}) == 1);
    fs::path large = outputDir() / "large.png";
    REQUIRE(test::runCliStatus({"render", scene, "-o", large.string(), "--linear16", "--width", "64", "--threads", "2"}) == 0);
    CHECK_THROWS_WITH_AS(compareImages(large.string(), reference), doctest::Contains("--width 320 --height 240"), Error);
    CHECK(test::runCliStatus({"render", scene, "-o", (outputDir() / "x.exr").string(), "--linear16"}) == 1);
    CHECK(test::runCliStatus({"render", scene, "-o", (outputDir() / "x.png").string(), "--linear16", "--srgb8"}) == 1);
}

namespace {

// An accelerator whose build stops in a stub, as the student's does before it is written.
class StubAccelerator : public Accelerator {
public:
    explicit StubAccelerator(std::string stub) : stub_(std::move(stub)) {}
    void build(const PrimitiveSet&) override { throw NotImplemented(stub_); }
    Hit intersect(const Ray&, TraversalStats&) const override { return {}; }
    bool occluded(const Ray&, TraversalStats&) const override { return false; }
    StructureView structure() const override { return {}; }
    size_t memoryBytes() const override { return 0; }

private:
    std::string stub_;
};

}  // namespace

TEST_CASE("render's accelerator: the default falls back to bvh-median from an a2 stub, and says so") {
    Scene scene = loadGltf(std::string(RTLAB_SOURCE_DIR) + "/scenes/cornell-box.gltf");
    PrimitiveSet primitives(scene);
    const std::string a2 = "a2 splitSahBuckets (assignments/a2_sah/sah_buckets.cpp)";
    // bvh-buckets stops in a2 as a student's does; the others are the real accelerators.
    cli::AcceleratorFactory studentWithoutA2 = [&](const AcceleratorSpec& spec) -> std::unique_ptr<Accelerator> {
        if (spec.name == "bvh-buckets") return std::make_unique<StubAccelerator>(a2);
        return makeAccelerator(spec);
    };
    AcceleratorSpec spec;
    std::ostringstream notes;
    auto accelerator = cli::buildRenderAccelerator(spec, false, primitives, studentWithoutA2, notes);
    CHECK(spec.name == "bvh-median");
    CHECK(accelerator->structure().nodes.size() > 0);
    CHECK(linesOf(notes.str()).size() == 1);
    CHECK(notes.str().find("--accel bvh-median") != std::string::npos);
    CHECK(notes.str().find("sah_buckets.cpp") != std::string::npos);

    // The stub's name is the student's build's: escaped on its way to the terminal.
    cli::AcceleratorFactory hostile = [&](const AcceleratorSpec& asked) -> std::unique_ptr<Accelerator> {
        if (asked.name == "bvh-buckets") return std::make_unique<StubAccelerator>("a2 \x1b[2Jsplit\nSahBuckets");
        return makeAccelerator(asked);
    };
    AcceleratorSpec again;
    std::ostringstream escaped;
    cli::buildRenderAccelerator(again, false, primitives, hostile, escaped);
    CHECK(escaped.str().find('\x1b') == std::string::npos);
    CHECK(linesOf(escaped.str()).size() == 1);

    // Asked for by name, or stopped in a1: no way round, the stub's error stands.
    AcceleratorSpec asked;
    CHECK_THROWS_AS(cli::buildRenderAccelerator(asked, true, primitives, studentWithoutA2, notes), NotImplemented);
    cli::AcceleratorFactory studentWithoutA1 = [](const AcceleratorSpec&) -> std::unique_ptr<Accelerator> {
        return std::make_unique<StubAccelerator>("a1 buildBvh (assignments/a1_bvh/bvh_build.cpp)");
    };
    AcceleratorSpec fresh;
    std::ostringstream none;
    CHECK_THROWS_AS(cli::buildRenderAccelerator(fresh, false, primitives, studentWithoutA1, none), NotImplemented);
    CHECK(none.str().empty());
}

TEST_CASE("bad input: nan and out-of-range numbers in a ray file, a garbage .glb: one line naming the file") {
    fs::path rays = outputDir() / "odd-rays.txt";
    std::ofstream(rays) << "0 0 0 0 0 -1\n0 0 nan 0 0 -1\n";
    CHECK_THROWS_WITH_AS(readRayFile(rays.string()), doctest::Contains("odd-rays.txt:2: 'nan' is not a number"), Error);
    std::ofstream(rays) << "# big\n1e40 0 0 0 0 -1\n";
    CHECK_THROWS_WITH_AS(readRayFile(rays.string()), doctest::Contains("odd-rays.txt:2: '1e40' is out of float range"), Error);
    std::ofstream(rays) << "0 0 0 inf 0 -1\n";
    CHECK_THROWS_WITH_AS(readRayFile(rays.string()), doctest::Contains("odd-rays.txt:1: 'inf' is infinite"), Error);
    std::ofstream(rays) << "0 0 0 0 0 -1 0 inf\n";  // tmax may be inf: writeRayFile writes it so
    CHECK(readRayFile(rays.string()).size() == 1);

    fs::path glb = outputDir() / "garbage.glb";
    std::ofstream(glb) << "this is not a binary glTF at all {";
    try {
        loadGltf(glb.string());
        FAIL("a garbage .glb loaded");
    } catch (const Error& e) {
        std::string message = e.what();
        CHECK(message.find("garbage.glb") != std::string::npos);
        CHECK(message.find("not a binary glTF") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.find("json") == std::string::npos);
    }
}
