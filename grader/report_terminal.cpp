// The terminal table: one line per test (status, points, one-line reason), a subtotal per
// assignment and the total.
#include "grader/grading_report.h"
#include "grader/untrusted_text.h"

#include <cstdio>
#include <map>

namespace rtlab::grader {
namespace {

constexpr size_t kReasonWidth = 110;

const char* statusColour(TestStatus status) {
    switch (status) {
    case TestStatus::Passed: return "\033[32m";
    case TestStatus::Failed: return "\033[31m";
    case TestStatus::NotStarted: return "\033[33m";
    }
    return "";
}

std::string points(double score, double max) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%6.2f/%-6.2f", score, max);
    return buffer;
}

}  // namespace

void printTerminalReport(const GradingReport& untrusted, std::ostream& out, bool colour) {
    const GradingReport report = displaySafe(untrusted);
    size_t nameWidth = 4;
    for (const TestResult& t : report.tests) nameWidth = std::max(nameWidth, t.name.size());
    auto pad = [](std::string s, size_t width) {
        s.resize(std::max(s.size(), width), ' ');
        return s;
    };
    out << "Grading " << report.implementation << " (seed " << report.seed << ")\n\n";
    out << pad("test", nameWidth) << "  " << pad("status", 11) << "  " << pad("points", 13) << "  reason\n";
    std::map<std::string, std::pair<double, double>> perAssignment;
    std::string current;
    for (const TestResult& t : report.tests) {
        if (t.assignment != current) {
            if (!current.empty()) out << "\n";
            current = t.assignment;
        }
        std::string reason = t.reason;
        if (reason.size() > kReasonWidth) reason = truncateUtf8(reason, kReasonWidth - 3) + "...";
        std::string status = pad(testStatusName(t.status), 11);
        if (colour) status = statusColour(t.status) + status + "\033[0m";
        out << pad(t.name, nameWidth) << "  " << status << "  " << points(t.score, t.maxScore) << "  " << reason << "\n";
        perAssignment[t.assignment].first += t.score;
        perAssignment[t.assignment].second += t.maxScore;
    }
    out << "\n";
    for (const auto& [assignment, sum] : perAssignment)
        out << pad(assignment, nameWidth) << "  " << pad("", 11) << "  " << points(sum.first, sum.second) << "\n";
    char total[96];
    std::snprintf(total, sizeof total, "total: %.2f of %.2f points, %.1f s", report.score(), report.maxScore(), report.seconds);
    out << total << "\n";
}

}  // namespace rtlab::grader
