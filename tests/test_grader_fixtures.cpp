// The grader's fixtures (grader/fixtures/, docs/grading.md "Fixtures"): broken and cheating
// submissions, each built through `rtlab grade --submissions` exactly as an instructor would,
// must get the verdict grader/fixtures/expectations.json names and score nothing.
#include "grader/grading_report.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rtlab::grader;

TEST_CASE("grader fixtures: every broken submission gets its verdict and no points") {
    const fs::path source = RTLAB_SOURCE_DIR, binary = RTLAB_BINARY_DIR;
    const fs::path work = fs::temp_directory_path() / ("rtlab-fixtures-" + std::to_string(::getpid()));
    fs::create_directories(work);
    auto expectations = nlohmann::json::parse(std::ifstream(source / "grader/fixtures/expectations.json"));
    for (const auto& [name, expected] : expectations.at("fixtures").items())
        for (const auto& path : expected.value("not_created", nlohmann::json::array())) fs::remove(path.get<std::string>());

    // Run from `work`, so relative paths a fixture tries to write would land there.
    std::string command = "cd '" + work.string() + "' && '" + (binary / "rtlab-solution").string() + "' grade --submissions '" +
                          (source / "grader/fixtures").string() + "' --jobs 2 --csv grades.csv --time-limit 1 --memory-limit 256" +
                          " --assignment a0 --assignment a1 --models '" + (binary / "models").string() + "' --work '" +
                          (work / "grading").string() + "' > batch.log 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    REQUIRE(fs::exists(work / "grades.csv"));

    for (const auto& [name, expected] : expectations.at("fixtures").items()) {
        CAPTURE(name);
        GradingReport report = readJsonReport((work / "grades-reports" / (name + ".json")).string());
        CHECK(report.score() == 0.0);
        const TestResult* test = nullptr;
        for (const TestResult& t : report.tests)
            if (t.name == expected.at("test").get<std::string>()) test = &t;
        REQUIRE(test != nullptr);
        CAPTURE(test->reason);
        CHECK(testStatusName(test->status) == expected.at("status").get<std::string>());
        if (expected.contains("reason")) CHECK(test->reason.find(expected.at("reason").get<std::string>()) != std::string::npos);
        if (expected.contains("details")) CHECK(testOutput(*test).find(expected.at("details").get<std::string>()) != std::string::npos);
        if (expected.contains("student_output"))
            CHECK(report.studentOutput.find(expected.at("student_output").get<std::string>()) != std::string::npos);
        for (const auto& path : expected.value("not_created", nlohmann::json::array())) {
            CHECK_FALSE(fs::exists(path.get<std::string>()));
            CHECK_FALSE(fs::exists(work / path.get<std::string>()));
        }
    }
    fs::remove_all(work);
}
