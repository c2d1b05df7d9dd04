// The grader's fixtures (grader/fixtures/, docs/grading.md "Fixtures"): hostile and broken
// submissions, each graded through `rtlab grade --submissions` exactly as an instructor would,
// must get the verdict grader/fixtures/expectations.json names and no point they should not.
#include "grader/compile_sandbox.h"
#include "grader/grading_report.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

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

const std::vector<std::string> kDefaultAssignments{"a0", "a1"};

// The assignments a fixture is graded on: its "assignments", a0 and a1 unless it names others.
std::vector<std::string> gradedAssignments(const nlohmann::json& expected) {
    return expected.value("assignments", kDefaultAssignments);
}

// The submissions folder a batch grades: each fixture as it is, or laid over a copy of the
// reference solutions when it says with_solutions.
fs::path assembleSubmissions(const std::vector<std::string>& names, const nlohmann::json& fixtures, const fs::path& source, const fs::path& into) {
    for (const std::string& name : names) {
        const nlohmann::json& expected = fixtures.at(name);
        fs::path target = into / name;
        fs::create_directories(target / "assignments");
        if (expected.value("with_solutions", false))
            fs::copy(source / "solutions", target / "assignments", fs::copy_options::recursive);
        if (fs::exists(source / "grader/fixtures" / name))
            fs::copy(source / "grader/fixtures" / name, target, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        if (expected.contains("patch")) applyPatch(target, expected.at("patch"));
    }
    return into;
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
    // One batch per list of assignments graded, each in a folder of its own.
    std::map<std::vector<std::string>, std::vector<std::string>> batches;
    for (const auto& [name, expected] : fixtures.items()) batches[gradedAssignments(expected)].push_back(name);
    std::map<std::string, fs::path> reportOf;
    for (const auto& [assignments, names] : batches) {
        std::string label, options;
        for (const std::string& a : assignments) {
            label += (label.empty() ? "" : "-") + a;
            options += " --assignment " + a;
        }
        fs::path batch = work / label;
        fs::create_directories(batch);
        fs::path submissions = assembleSubmissions(names, fixtures, source, batch / "submissions");
        // The a0 and a1 batch stops endless loops after 1 s (their verdicts name it); the others
        // keep the grader's default: one of a6's estimator phases takes about a second of CPU
        // time, the reference's too.
        if (assignments == kDefaultAssignments) options += " --time-limit 1";
        // Run from the batch's folder, so relative paths a fixture tries to write would land there.
        std::string command = "cd '" + batch.string() + "' && '" + (binary / "rtlab-solution").string() + "' grade --submissions '" +
                              submissions.string() + "' --jobs 2 --csv grades.csv --memory-limit 256 --compile-time-limit 40" + options +
                              " --models '" + (binary / "models").string() + "' --work '" + (batch / "grading").string() + "' > batch.log 2>&1";
        INFO(label);
        REQUIRE(std::system(command.c_str()) == 0);
        REQUIRE(fs::exists(batch / "grades.csv"));
        for (const std::string& name : names) reportOf[name] = batch / "grades-reports" / (name + ".json");
    }

    for (const auto& [name, expected] : fixtures.items()) {
        CAPTURE(name);
        GradingReport report = readJsonReport(reportOf.at(name).string());
        if (expected.contains("score_at_least")) {
            CHECK(report.score() >= expected.at("score_at_least").get<double>());
            if (expected.contains("score_below")) CHECK(report.score() < expected.at("score_below").get<double>());
        } else {
            CHECK(report.score() == 0.0);
        }
        CHECK(report.maxScore() > 0.0);
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
        if (expected.contains("details")) CHECK(testOutput(*test).find(expected.at("details").get<std::string>()) != std::string::npos);
        if (expected.contains("student_output"))
            CHECK(report.studentOutput.find(expected.at("student_output").get<std::string>()) != std::string::npos);
        for (const auto& path : expected.value("not_created", nlohmann::json::array())) {
            CHECK_FALSE(fs::exists(path.get<std::string>()));
            CHECK_FALSE(fs::exists(reportOf.at(name).parent_path().parent_path() / path.get<std::string>()));
        }
    }
    fs::remove_all(work);
}
