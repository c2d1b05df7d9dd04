// The two JSON reports: rtlab's own (read back by --submission) and Gradescope's results.json.
#include "framework/core/error.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/json_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace rtlab::grader {

namespace {

void writeText(const std::string& path, const std::string& text) {
    std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw Error(path + ": cannot write the report");
}

// displaySafe has made every string valid UTF-8; replacing what is not is only the guard that
// dump() can never throw while a report is written.
std::string dumped(const nlohmann::ordered_json& json) {
    return json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

TestStatus parseStatus(const std::string& s) {
    if (s == "passed") return TestStatus::Passed;
    if (s == "not started") return TestStatus::NotStarted;
    return TestStatus::Failed;
}

}  // namespace

void writeJsonReport(const GradingReport& untrusted, const std::string& path) {
    const GradingReport report = displaySafe(untrusted);
    nlohmann::ordered_json json;
    json["score"] = report.score();
    json["max_score"] = report.maxScore();
    json["implementation"] = report.implementation;
    json["seed"] = report.seed;
    json["execution_time"] = report.seconds;
    json["student_output"] = report.studentOutput;
    json["isolation"] = report.isolation;
    json["tests"] = nlohmann::ordered_json::array();
    for (const TestResult& t : report.tests) {
        nlohmann::ordered_json images = nlohmann::ordered_json::array();
        for (const ReportImage& image : t.images) images.push_back({{"label", image.label}, {"path", image.path}});
        json["tests"].push_back({{"name", t.name},
                                 {"assignment", t.assignment},
                                 {"status", testStatusName(t.status)},
                                 {"score", t.score},
                                 {"max_score", t.maxScore},
                                 {"fraction", t.fraction},
                                 {"visibility", t.visibility},
                                 {"output", testOutput(t)},
                                 {"reason", t.reason},
                                 {"details", t.details},
                                 {"images", images},
                                 {"seconds", t.seconds}});
    }
    writeText(path, dumped(json));
}

GradingReport readJsonReport(const std::string& path) {
    const nlohmann::json json = readJsonFile(path, "grading report", "cannot read the grading report");
    GradingReport report;
    try {
        report.implementation = json.value("implementation", "");
        report.seed = json.value("seed", uint64_t(0));
        report.seconds = json.value("execution_time", 0.0);
        report.studentOutput = json.value("student_output", "");
        report.isolation = json.value("isolation", "");
        for (const auto& t : json.at("tests")) {
            TestResult r;
            r.name = t.at("name").get<std::string>();
            r.assignment = t.value("assignment", "");
            r.status = parseStatus(t.at("status").get<std::string>());
            r.score = t.at("score").get<double>();
            r.maxScore = t.at("max_score").get<double>();
            r.fraction = t.value("fraction", 0.0);
            r.visibility = t.value("visibility", "visible");
            r.reason = t.value("reason", "");
            r.details = t.value("details", std::vector<std::string>{});
            r.seconds = t.value("seconds", 0.0);
            for (const auto& image : t.value("images", nlohmann::json::array()))
                r.images.push_back({image.at("label").get<std::string>(), image.at("path").get<std::string>()});
            report.tests.push_back(std::move(r));
        }
    } catch (const nlohmann::json::exception& e) {
        throw Error(path + ": malformed grading report (" + e.what() + ")");
    }
    return report;
}

void writeGradescopeResults(const GradingReport& untrusted, const std::string& path) {
    const GradingReport report = displaySafe(untrusted);
    nlohmann::ordered_json json;
    json["score"] = report.score();
    json["execution_time"] = report.seconds;
    char summary[160];
    std::snprintf(summary, sizeof summary, "rtlab grader: %.2f of %.2f points (seed %llu). Failing tests name the first wrong cases.",
                  report.score(), report.maxScore(), static_cast<unsigned long long>(report.seed));
    json["output"] = summary;
    json["output_format"] = "text";
    json["test_output_format"] = "text";
    json["visibility"] = "visible";
    json["stdout_visibility"] = "hidden";
    json["tests"] = nlohmann::ordered_json::array();
    int number = 0;
    for (const TestResult& t : report.tests) {
        json["tests"].push_back({{"name", t.name},
                                 {"number", std::to_string(++number)},
                                 {"score", t.score},
                                 {"max_score", t.maxScore},
                                 {"status", t.status == TestStatus::Passed ? "passed" : "failed"},
                                 {"output", std::string(testStatusName(t.status)) + (t.reason.empty() && t.details.empty() ? "" : ": ") +
                                                testOutput(t)},
                                 {"output_format", "text"},
                                 {"visibility", t.visibility},
                                 {"tags", {t.assignment}}});
    }
    writeText(path, dumped(json));
}

}  // namespace rtlab::grader
