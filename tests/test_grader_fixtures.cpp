// The grader's fixtures (grader/fixtures/, docs/grading.md "Fixtures"): hostile and broken
// submissions, each graded through `rtlab grade --submissions` exactly as an instructor would,
// must get the verdict grader/fixtures/expectations.json names and no point they should not.
#include "grader/engine/compile_sandbox.h"
#include "grader/engine/grading_report.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rtlab::grader;

namespace {

void applyPatch(const fs::path& submission, const nlohmann::json& patch) {
    fs::path file = submission / patch.at("file").get<std::string>();
    std::ifstream in(file);
    std::string text(std::istreambuf_iterator<char>(in), {});
    std::string from = patch.at("replace"), to = patch.at("with");
    size_t replaced = 0;
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()), ++replaced) text.replace(at, from.size(), to);
    std::string problem = file.string() + " no longer contains the patched text " + from;
    REQUIRE_MESSAGE(replaced > 0, problem);
    std::ofstream(file) << text;
}

// The links a fixture asks for ("links": path in the submission -> target, where <source> is the
// repository and <submissions> the folder of all submissions), made after copying: git and
// the copy would follow them.
void makeLinks(const fs::path& submission, const nlohmann::json& links, const fs::path& source, const fs::path& submissions) {
    for (const auto& [at, target] : links.items()) {
        std::string to = target.get<std::string>();
        for (auto [mark, value] : {std::pair<std::string, std::string>{"<source>", source.string()}, {"<submissions>", submissions.string()}})
            if (to.rfind(mark, 0) == 0) to = value + to.substr(mark.size());
        fs::remove_all(submission / at);
        fs::create_directories((submission / at).parent_path());
        fs::create_directory_symlink(to, submission / at);
    }
}

// The submissions folder the batch grades: each fixture as it is, or laid over a copy of the
// reference solutions when it says with_solutions.
fs::path assembleSubmissions(const nlohmann::json& fixtures, const fs::path& source, const fs::path& into) {
    for (const auto& [name, expected] : fixtures.items()) {
        fs::path target = into / name;
        fs::create_directories(target / "assignments");
        if (expected.value("with_solutions", false))
            fs::copy(source / "solutions", target / "assignments", fs::copy_options::recursive);
        if (fs::exists(source / "grader/fixtures" / name))
            fs::copy(source / "grader/fixtures" / name, target, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        if (expected.contains("patch")) applyPatch(target, expected.at("patch"));
    }
    for (const auto& [name, expected] : fixtures.items())
        if (expected.contains("links")) makeLinks(into / name, expected.at("links"), source, into);
    return into;
}

// The fixtures by the assignments they are graded on ("assignments", a0 and a1 unless said):
// one batch each.
const std::vector<std::string> kDefaultAssignments{"a0", "a1"};

std::map<std::vector<std::string>, nlohmann::json> byAssignments(const nlohmann::json& fixtures) {
    std::map<std::vector<std::string>, nlohmann::json> batches;
    for (const auto& [name, expected] : fixtures.items()) {
        std::vector<std::string> assignments = expected.value("assignments", kDefaultAssignments);
        batches[assignments][name] = expected;
    }
    return batches;
}

void checkFixture(const std::string& name, const nlohmann::json& expected, const fs::path& work) {
    CAPTURE(name);
    const fs::path reportPath = work / "grades-reports" / (name + ".json");
    GradingReport report = readJsonReport(reportPath.string());
    if (expected.contains("score_at_least")) {
        CHECK(report.score() >= expected.at("score_at_least").get<double>());
        if (expected.contains("score_below")) CHECK(report.score() < expected.at("score_below").get<double>());
    } else {
        CHECK(report.score() == 0.0);
    }
    CHECK(report.maxScore() > 0.0);
    // Every test the graded assignments define is listed, whatever the worker sent.
    if (expected.contains("max_score")) CHECK(report.maxScore() == expected.at("max_score").get<double>());
    if (expected.contains("report_bytes_below")) CHECK(fs::file_size(reportPath) < expected.at("report_bytes_below").get<uintmax_t>());
    CHECK(report.isolation.find("a seccomp filter loaded at its first instruction") != std::string::npos);
    CHECK(report.isolation.find("bubblewrap mount namespace") != std::string::npos);
    const TestResult* test = nullptr;
    for (const TestResult& t : report.tests)
        if (t.name == expected.at("test").get<std::string>()) test = &t;
    REQUIRE(test != nullptr);
    CAPTURE(test->reason);
    CAPTURE(testOutput(*test));
    CHECK(testStatusName(test->status) == expected.at("status").get<std::string>());
    if (expected.contains("reason")) CHECK(test->reason.find(expected.at("reason").get<std::string>()) != std::string::npos);
    if (expected.contains("reason_bytes_below")) CHECK(test->reason.size() < expected.at("reason_bytes_below").get<size_t>());
    if (expected.contains("details")) CHECK(testOutput(*test).find(expected.at("details").get<std::string>()) != std::string::npos);
    if (expected.contains("student_output"))
        CHECK(report.studentOutput.find(expected.at("student_output").get<std::string>()) != std::string::npos);
    for (const auto& path : expected.value("not_created", nlohmann::json::array())) {
        CHECK_FALSE(fs::exists(path.get<std::string>()));
        CHECK_FALSE(fs::exists(work / path.get<std::string>()));
    }
}

}  // namespace

TEST_CASE("grader fixtures: every hostile or broken submission gets its verdict and no point it should not") {
    // The verdicts of the include and .incbin fixtures are those of the compile sandbox.
    REQUIRE_MESSAGE(CompileSandbox::detect().usesNamespaces(), CompileSandbox::detect().description());
    const fs::path source = RTLAB_SOURCE_DIR, binary = RTLAB_BINARY_DIR;
    const fs::path work = fs::temp_directory_path() / ("rtlab-fixtures-" + std::to_string(::getpid()));
    fs::create_directories(work);
    auto fixtures = nlohmann::json::parse(std::ifstream(source / "grader/fixtures/expectations.json")).at("fixtures");
    for (const auto& [name, expected] : fixtures.items())
        for (const auto& path : expected.value("not_created", nlohmann::json::array())) fs::remove(path.get<std::string>());
    for (const auto& [assignments, batch] : byAssignments(fixtures)) {
        std::string list, folder = "batch";
        for (const std::string& a : assignments) {
            list += " --assignment " + a;
            folder += "-" + a;
        }
        CAPTURE(list);
        const fs::path batchWork = work / folder;
        fs::create_directories(batchWork);
        fs::path submissions = assembleSubmissions(batch, source, batchWork / "submissions");
        // The a0 and a1 batch stops endless loops after 1 s (their verdicts name it); the others
        // keep the grader's default: one of a6's estimator phases takes about a second of CPU
        // time, the reference's too.
        if (assignments == kDefaultAssignments) list += " --time-limit 1";
        // Run from the batch's folder, so relative paths a fixture tries to write would land there.
        std::string command = "cd '" + batchWork.string() + "' && '" + (binary / "rtlab-solution").string() + "' grade --submissions '" +
                              submissions.string() + "' --jobs 2 --csv grades.csv --memory-limit 256 --compile-time-limit 40" +
                              list + " --models '" + (binary / "models").string() + "' --work '" + (batchWork / "grading").string() +
                              "' > batch.log 2>&1";
        REQUIRE(std::system(command.c_str()) == 0);
        REQUIRE(fs::exists(batchWork / "grades.csv"));
        for (const auto& [name, expected] : batch.items()) checkFixture(name, expected, batchWork);
    }
    fs::remove_all(work);
}
