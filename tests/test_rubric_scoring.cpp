// The rubric's scoring rules (docs/grading.md, "The rubric"): scores rounded to its precision,
// and only the tests the grader defines earn points.
#include "framework/core/error.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/grading_rubric.h"
#include "grader/engine/submission_toolchain.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rtlab::grader;

namespace {

fs::path writeRubric(const std::string& name, const std::string& text) {
    fs::path path = fs::temp_directory_path() / ("rtlab-rubric-" + std::to_string(::getpid()) + "-" + name + ".json");
    std::ofstream(path) << text;
    return path;
}

TestResult result(const std::string& name, TestStatus status, double fraction) {
    TestResult r;
    r.assignment = name.substr(0, name.find('/'));
    r.name = name;
    r.status = status;
    r.fraction = fraction;
    return r;
}

}  // namespace

TEST_CASE("rubric: scores are rounded to its precision") {
    fs::path one = writeRubric("one", R"({"precision": 1, "rules": [{"match": "*", "points": 10}]})");
    std::vector<TestResult> results = {result("a0/x", TestStatus::Failed, 2.0 / 3.0)};
    Rubric::load(one.string()).apply(results);
    CHECK(results[0].score == 6.7);
    Rubric rubric = loadGradingRubric(RTLAB_SOURCE_DIR, "");
    CHECK(rubric.precision() == 2);
    rubric.apply(results);
    CHECK(results[0].maxScore == 1.0);  // the shipped rubric's catch-all
    CHECK(results[0].score == 0.67);
    CHECK(rubric.round(1.005001) == 1.01);
    fs::remove(one);
}

TEST_CASE("report totals are the decimal sums of the rounded scores") {
    GradingReport report;
    double plain = 0.0;
    for (double score : {0.1, 0.2, 0.3}) {
        TestResult t;
        t.score = t.maxScore = score;
        report.tests.push_back(t);
        plain += score;
    }
    REQUIRE(plain != 0.6);  // 0.6000000000000001
    CHECK(report.score() == 0.6);
    CHECK(report.maxScore() == 0.6);
}

TEST_CASE("rubric: a malformed precision is an error naming the file") {
    for (const char* bad : {R"("2")", "-1", "7", "1.5"}) {
        fs::path path = writeRubric("bad", std::string(R"({"precision": )") + bad + R"(, "rules": []})");
        CAPTURE(bad);
        std::string expected = path.string() + ": \"precision\"";
        CHECK_THROWS_WITH_AS(Rubric::load(path.string()), doctest::Contains(expected.c_str()), rtlab::Error);
        fs::remove(path);
    }
}

// One reader serves the three (grader/engine/json_file.h): each message is one line that names
// the file and says what it should have been.
TEST_CASE("rubric, toolchain and saved report: a missing or malformed file is one line naming it") {
    struct Reader {
        const char* what;
        void (*read)(const std::string&);
    };
    const Reader readers[] = {
        {"rubric", [](const std::string& p) { Rubric::load(p); }},
        {"toolchain", [](const std::string& p) { readToolchain(p); }},
        {"grading report", [](const std::string& p) { readJsonReport(p); }},
    };
    fs::path broken = writeRubric("truncated", R"({"rules": [)");
    fs::path missing = fs::temp_directory_path() / ("rtlab-rubric-" + std::to_string(::getpid()) + "-absent.json");
    for (const Reader& reader : readers) {
        CAPTURE(reader.what);
        std::string message;
        try {
            reader.read(broken.string());
        } catch (const rtlab::Error& e) {
            message = e.what();
        }
        CHECK(message.rfind(broken.string() + ": malformed " + reader.what + " (", 0) == 0);
        CHECK(message.find('\n') == std::string::npos);
        message.clear();
        try {
            reader.read(missing.string());
        } catch (const rtlab::Error& e) {
            message = e.what();
        }
        CHECK(message.rfind(missing.string() + ": ", 0) == 0);
        CHECK(message.find('\n') == std::string::npos);
    }
    fs::remove(broken);
}

TEST_CASE("rubric: only the grader's own tests earn points") {
    fs::path path = writeRubric("defined", R"({"rules": [{"match": "a0/*", "points": 10}, {"match": "*", "points": 1}]})");
    Rubric rubric = Rubric::load(path.string());
    std::vector<TestResult> defined = {result("a0/slab/face-planes", TestStatus::Failed, 0),
                                       result("a0/sphere/cases", TestStatus::Failed, 0)};
    std::vector<TestResult> reported = {
        result("a0/slab/face-planes", TestStatus::Passed, 1.0),
        result("a0/invented/bonus", TestStatus::Passed, 1.0),        // a name the grader never made
        result("a0/slab/face-planes", TestStatus::Passed, 1.0),      // the same test twice counts once
        result("a0/sphere/cases", TestStatus::Passed, 50.0),         // a fraction above 1
    };
    std::vector<TestResult> scored = rubric.applyToDefined(defined, reported, "not graded");
    REQUIRE(scored.size() == 2);
    CHECK(scored[0].name == "a0/slab/face-planes");
    CHECK(scored[0].score == 10.0);
    CHECK(scored[1].score == 10.0);  // clamped to the whole of the test's points, no more
    double total = scored[0].score + scored[1].score;
    CHECK(total == 20.0);

    std::vector<TestResult> nothing = rubric.applyToDefined(defined, {result("a0/sphere/cases", TestStatus::Passed, NAN)}, "not graded");
    CHECK(nothing[0].reason == "not graded");
    CHECK(nothing[0].maxScore == 10.0);  // a missing test is 0 of its points, never 0 of 0
    CHECK(nothing[1].score == 0.0);
    CHECK(nothing[1].status == TestStatus::Failed);
    fs::remove(path);
}
