#include "grader/engine/grades_csv.h"

#include "framework/core/error.h"
#include "grader/engine/grading_report.h"
#include "framework/core/untrusted_text.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// Quoted, one line, and never read as a formula by a spreadsheet (a folder name is whatever the
// student or the upload chose).
std::string textField(const std::string& text) {
    std::string safe = escapeUntrusted(text, TextLayout::OneLine);
    if (!safe.empty() && std::string("=+-@").find(safe.front()) != std::string::npos) safe = "'" + safe;
    std::string quoted = "\"";
    for (char c : safe) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string numberField(double value, int precision) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", precision, value);
    return buffer;
}

// Why a submission's row is not a full grading: its build test's reason when that failed.
std::string rowReason(const GradingReport& report) {
    for (const TestResult& t : report.tests)
        if (t.name == "build" && t.status != TestStatus::Passed) return t.reason;
    return "";
}

}  // namespace

std::vector<std::string> reportsInFolders(const std::vector<std::string>& folders) {
    std::map<std::string, std::string> byName;
    for (const std::string& folder : folders) {
        std::error_code error;
        fs::directory_iterator it(folder, error);
        if (error) throw Error(folder + ": cannot read the reports folder (" + error.message() + ")");
        for (const fs::directory_entry& entry : it) {
            if (entry.path().extension() != ".json" || !entry.is_regular_file(error)) continue;
            auto [at, inserted] = byName.emplace(entry.path().filename().string(), entry.path().string());
            if (!inserted) throw Error(entry.path().string() + ": " + at->second + " reports the same submission");
        }
    }
    std::vector<std::string> paths;
    for (const auto& [name, path] : byName) paths.push_back(path);
    return paths;
}

void writeGradesCsv(const std::vector<std::string>& reportPaths, const std::string& csvPath, int precision) {
    std::vector<std::pair<std::string, GradingReport>> rows;
    for (const std::string& path : reportPaths) rows.emplace_back(fs::path(path).stem().string(), readJsonReport(path));
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

    std::vector<std::string> columns;
    std::set<std::string> seen;
    for (const auto& [name, report] : rows)
        for (const TestResult& t : report.tests)
            if (seen.insert(t.name).second) columns.push_back(t.name);

    std::string temporary = csvPath + ".partial";
    {
        std::ofstream csv(temporary, std::ios::binary);
        csv << "submission,score,max_score,reason";
        for (const std::string& c : columns) csv << "," << textField(c);
        csv << "\n";
        for (const auto& [name, report] : rows) {
            std::map<std::string, double> scores;
            for (const TestResult& t : report.tests) scores.try_emplace(t.name, t.score);
            csv << textField(name) << "," << numberField(report.score(), precision) << "," << numberField(report.maxScore(), precision)
                << "," << textField(rowReason(report));
            for (const std::string& c : columns) {
                auto it = scores.find(c);
                csv << "," << (it == scores.end() ? "" : numberField(it->second, precision));
            }
            csv << "\n";
        }
        if (!csv.flush()) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw Error(csvPath + ": cannot write the CSV");
        }
    }
    std::error_code error;
    fs::rename(temporary, csvPath, error);
    if (error) throw Error(csvPath + ": cannot write the CSV (" + error.message() + ")");
}

}  // namespace rtlab::grader
