// Byte-safe reports (docs/grading.md, "Reports"): every hostile byte class student code or a
// compiler can emit goes through every report writer; each output stays valid for its format
// (JSON parses, JUnit XML passes xmllint against grader/schemas/junit-10.xsd, HTML is valid
// UTF-8, no raw ESC reaches the terminal, the grades CSV merged from the JSON report is valid
// UTF-8 with the submission's hostile folder name escaped) and no score changes.
#include "grader/engine/grades_csv.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/grading_rubric.h"
#include "framework/core/untrusted_text.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rtlab::grader;

namespace {

struct HostileBytes {
    const char* name;
    std::string bytes;
    const char* visible;  // how escapeUntrusted shows (part of) it
};

const std::vector<HostileBytes>& hostileClasses() {
    static const std::vector<HostileBytes> classes = {
        {"invalid UTF-8", std::string("bad \xff\xfe byte"), "\\xff\\xfe"},
        {"cut multibyte", std::string("cut \xe2\x82", 6), "\\xe2\\x82"},
        {"Latin-1", std::string("caf\xe9 na\xefve"), "caf\\xe9"},
        {"NUL", std::string("nul\0byte", 8), "nul\\x00byte"},
        {"ESC sequence", std::string("\x1b[2J\x1b]0;owned\x07 clear"), "\\x1b[2J"},
        {"CSI as C1", std::string("\xc2\x9b" "31m red"), "\\u{009B}31m"},
        {"C1 controls", std::string("nel\xc2\x85 end"), "\\u{0085}"},
        {"DEL and CR", std::string("del\x7f cr\rover"), "\\x7f"},
        {"overlong slash", std::string("\xc0\xaf"), "\\xc0\\xaf"},
        {"surrogate", std::string("\xed\xa0\x80"), "\\xed\\xa0\\x80"},
        {"bidi override", std::string("\xe2\x80\xae" "evil"), "\\u{202E}"},
        {"XML-forbidden noncharacter", std::string("\xef\xbf\xbf"), "\\u{FFFF}"},
    };
    return classes;
}

bool validUtf8WithoutControls(const std::string& text, bool allowEsc) {
    // A text is what escapeUntrusted leaves alone exactly when it needs no escape.
    std::string withoutColour = text;
    if (allowEsc)
        for (const char* code : {"\033[32m", "\033[31m", "\033[33m", "\033[0m"})
            for (size_t at; (at = withoutColour.find(code)) != std::string::npos;) withoutColour.erase(at, std::string(code).size());
    return escapeUntrusted(withoutColour, TextLayout::Lines) == withoutColour;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A passed test and a partly failed one, each carrying the hostile bytes everywhere text goes.
GradingReport hostileReport(const HostileBytes& hostile, const Rubric& rubric) {
    GradingReport report;
    report.implementation = "submission " + hostile.bytes;
    report.seed = 7;
    report.seconds = 1.5;
    report.studentOutput = "printed: " + hostile.bytes + "\nsecond line\t" + hostile.bytes;
    TestResult passed;
    passed.assignment = "a0";
    passed.name = "a0/slab/face-planes";
    passed.status = TestStatus::Passed;
    passed.fraction = 1.0;
    passed.details = {"student said " + hostile.bytes};
    passed.seconds = 0.25;
    TestResult failed;
    failed.assignment = "a0";
    failed.name = "a0/triangle/edges-and-winding";
    failed.status = TestStatus::Failed;
    failed.fraction = 0.5;
    failed.reason = "1 of 2 cases wrong; compiler said " + hostile.bytes;
    failed.details = {hostile.bytes, "line with " + hostile.bytes};
    report.tests = {passed, failed};
    rubric.apply(report.tests);
    return report;
}

}  // namespace

TEST_CASE("escapeUntrusted: valid UTF-8 and layout pass, everything else becomes a visible escape") {
    CHECK(escapeUntrusted("plain ascii, \xc3\xa9t\xc3\xa9, \xe2\x82\xac, \xf0\x9f\x98\x80\n\ttabbed") ==
          "plain ascii, \xc3\xa9t\xc3\xa9, \xe2\x82\xac, \xf0\x9f\x98\x80\n\ttabbed");
    CHECK(escapeUntrusted("two\nlines\t.", TextLayout::OneLine) == "two\\x0alines\\x09.");
    for (const HostileBytes& h : hostileClasses()) {
        CAPTURE(h.name);
        std::string escaped = escapeUntrusted(h.bytes);
        CHECK(escaped.find(h.visible) != std::string::npos);
        CHECK(escapeUntrusted(escaped) == escaped);  // idempotent: pure ASCII escapes
        CHECK(validUtf8WithoutControls(escaped, false));
    }
    CHECK(truncateUtf8("ab\xe2\x82\xac", 4) == "ab");
    CHECK(truncateUtf8("ab\xe2\x82\xac", 5) == "ab\xe2\x82\xac");
}

TEST_CASE("every report writer: hostile bytes are escaped, outputs stay valid, scores unchanged") {
    const fs::path source = RTLAB_SOURCE_DIR;
    const fs::path work = fs::temp_directory_path() / ("rtlab-escaping-" + std::to_string(::getpid()));
    fs::create_directories(work);
    Rubric rubric = loadGradingRubric(source.string(), "");
    for (const HostileBytes& hostile : hostileClasses()) {
        CAPTURE(hostile.name);
        GradingReport report = hostileReport(hostile, rubric);
        const double score = report.score(), maxScore = report.maxScore();
        REQUIRE(score == 15.0);  // 10 for the passed test, half of 10 for the other
        REQUIRE(maxScore == 20.0);

        std::ostringstream plain, coloured;
        printTerminalReport(report, plain, false);
        printTerminalReport(report, coloured, true);
        CHECK(plain.str().find('\x1b') == std::string::npos);
        CHECK(validUtf8WithoutControls(plain.str(), false));
        CHECK(validUtf8WithoutControls(coloured.str(), true));  // only the table's own colours
        CHECK(plain.str().find(hostile.visible) != std::string::npos);

        fs::path json = work / "report.json", gradescope = work / "results.json", junit = work / "junit.xml", html = work / "html";
        REQUIRE_NOTHROW(writeJsonReport(report, json.string()));
        REQUIRE_NOTHROW(writeGradescopeResults(report, gradescope.string()));
        REQUIRE_NOTHROW(writeJunitReport(report, junit.string()));
        REQUIRE_NOTHROW(writeHtmlReport(report, html.string()));

        auto parsed = nlohmann::json::parse(readFile(json));  // throws on invalid UTF-8
        CHECK(parsed.at("score").get<double>() == score);
        CHECK(parsed.at("student_output").get<std::string>().find(hostile.visible) != std::string::npos);
        GradingReport back = readJsonReport(json.string());
        CHECK(back.score() == score);
        CHECK(back.maxScore() == maxScore);

        auto results = nlohmann::json::parse(readFile(gradescope));
        CHECK(results.at("score").get<double>() == score);
        CHECK(results.at("tests").at(1).at("output").get<std::string>().find(hostile.visible) != std::string::npos);

        std::string xmllint = "xmllint --noout --schema '" + (source / "grader/schemas/junit-10.xsd").string() + "' '" + junit.string() +
                              "' > '" + (work / "xmllint.log").string() + "' 2>&1";
        CHECK_MESSAGE(std::system(xmllint.c_str()) == 0, readFile(work / "xmllint.log"));
        CHECK(readFile(junit).find(hostile.visible) != std::string::npos);

        // The folder name is the report's file name: anything but '/' and NUL may be in it.
        if (hostile.bytes.find('\0') == std::string::npos) {
            fs::path named = work / ("student " + hostile.bytes + ".json"), csv = work / "grades.csv";
            fs::copy_file(json, named, fs::copy_options::overwrite_existing);
            REQUIRE_NOTHROW(writeGradesCsv({named.string()}, csv.string(), rubric.precision()));
            std::string sheet = readFile(csv);
            CHECK(validUtf8WithoutControls(sheet.substr(0, sheet.size() - 1), false));
            CHECK(sheet.find("\"student " + escapeUntrusted(hostile.bytes, TextLayout::OneLine) + "\",15.00,20.00,") != std::string::npos);
            fs::remove(named);
        }

        std::string page = readFile(html / "index.html");
        CHECK(validUtf8WithoutControls(page, false));
        CHECK(page.find(hostile.visible) != std::string::npos);
        std::string htmllint = "xmllint --html --noout '" + (html / "index.html").string() + "' > '" + (work / "xmllint.log").string() +
                               "' 2>&1";
        CHECK_MESSAGE(std::system(htmllint.c_str()) == 0, readFile(work / "xmllint.log"));
    }
    fs::remove_all(work);
}
