// The terminal table: one row per test (status, points, reason wrapped under the reason
// column), with --verbose the failing cases of every test that is not passing, a subtotal per
// assignment, the total and what to do next.
#include "grader/engine/grading_report.h"
#include "framework/core/untrusted_text.h"

#include <cstdint>
#include <cstdio>
#include <map>

namespace rtlab::grader {
namespace {

// Columns of the reason text: the common "not started: <stub> throws NotImplemented" fits on
// one row; a longer reason wraps onto further rows under the column instead of being cut.
constexpr size_t kReasonWidth = 100;

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

// The code point at text[i] and its length in bytes; a byte that starts no valid sequence
// counts as one character (displaySafe has escaped those already, so this is a fallback).
uint32_t codePointAt(const std::string& text, size_t i, size_t* length) {
    auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    unsigned char lead = byte(i);
    size_t n = lead < 0x80 ? 1 : lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
    if (i + n > text.size()) n = 1;
    uint32_t c = n == 1 ? lead : lead & (0x7F >> n);
    for (size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) {
            *length = 1;
            return lead;
        }
        c = (c << 6) | (byte(i + k) & 0x3F);
    }
    *length = n;
    return c;
}

// Columns a terminal gives a code point: the common combining marks take none, the East Asian
// wide and fullwidth blocks (CJK, Hangul, fullwidth forms, most emoji) two, the rest one.
size_t columnsOf(uint32_t c) {
    if ((c >= 0x0300 && c <= 0x036F) || (c >= 0x200B && c <= 0x200F) || (c >= 0xFE00 && c <= 0xFE0F)) return 0;
    if ((c >= 0x1100 && c <= 0x115F) || (c >= 0x2E80 && c <= 0xA4CF) || (c >= 0xAC00 && c <= 0xD7A3) ||
        (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFF60) ||
        (c >= 0xFFE0 && c <= 0xFFE6) || (c >= 0x1F300 && c <= 0x1FAFF) || (c >= 0x20000 && c <= 0x3FFFD))
        return 2;
    return 1;
}

}  // namespace

size_t displayWidth(const std::string& text) {
    size_t width = 0;
    for (size_t i = 0, n = 0; i < text.size(); i += n) width += columnsOf(codePointAt(text, i, &n));
    return width;
}

std::vector<std::string> wrapWords(const std::string& text, size_t width) {
    std::vector<std::string> lines;
    std::string line;
    size_t lineWidth = 0;
    size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        size_t end = text.find(' ', i);
        if (end == std::string::npos) end = text.size();
        std::string word = text.substr(i, end - i);
        size_t wordWidth = displayWidth(word);
        if (!line.empty() && lineWidth + 1 + wordWidth > width) {
            lines.push_back(line);
            line.clear();
            lineWidth = 0;
        }
        if (!line.empty()) {
            line += ' ';
            ++lineWidth;
        }
        line += word;
        lineWidth += wordWidth;
        i = end;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

std::string nextStepLine(const GradingReport& report) {
    for (const TestResult& t : report.tests) {
        if (t.status == TestStatus::Passed) continue;
        // A not-started reason names the stub that threw ("... (assignments/a1_bvh/bvh_build.cpp)
        // throws NotImplemented"): the file that stopped this test, more exact than the guide's.
        std::string stub = t.stub;
        size_t open = t.reason.find("(assignments/");
        if (open != std::string::npos) {
            size_t close = t.reason.find(')', open);
            if (close != std::string::npos) stub = t.reason.substr(open + 1, close - open - 1);
        }
        std::string line = "Next: " + t.name;
        if (!stub.empty()) line += " \u2014 " + stub;
        if (!t.docs.empty()) line += " \u2014 " + t.docs;
        return line;
    }
    return report.tests.empty() ? "Next: nothing was graded" : "Next: nothing, every test passes";
}

void printTerminalReport(const GradingReport& untrusted, std::ostream& out, bool colour, bool verbose) {
    const GradingReport report = displaySafe(untrusted);
    size_t nameWidth = 4;
    for (const TestResult& t : report.tests) nameWidth = std::max(nameWidth, displayWidth(t.name));
    auto pad = [](std::string s, size_t width) {
        size_t shown = displayWidth(s);
        if (shown < width) s.append(width - shown, ' ');
        return s;
    };
    const std::string reasonIndent(nameWidth + 2 + 11 + 2 + 13 + 2, ' ');
    out << "Grading " << report.implementation << " (seed " << report.seed << ")\n\n";
    out << pad("test", nameWidth) << "  " << pad("status", 11) << "  " << pad("points", 13) << "  reason\n";
    std::map<std::string, std::pair<double, double>> perAssignment;
    std::string current;
    for (const TestResult& t : report.tests) {
        if (t.assignment != current) {
            if (!current.empty()) out << "\n";
            current = t.assignment;
        }
        std::string status = pad(testStatusName(t.status), 11);
        if (colour) status = statusColour(t.status) + status + "\033[0m";
        std::vector<std::string> reason = wrapWords(t.reason, kReasonWidth);
        out << pad(t.name, nameWidth) << "  " << status << "  " << points(t.score, t.maxScore) << "  " << reason[0] << "\n";
        for (size_t k = 1; k < reason.size(); ++k) out << reasonIndent << reason[k] << "\n";
        if (verbose && t.status != TestStatus::Passed)
            for (const std::string& detail : t.details) {
                std::vector<std::string> lines = wrapWords(detail, kReasonWidth - 2);
                for (size_t k = 0; k < lines.size(); ++k) out << reasonIndent << (k ? "  " : "- ") << lines[k] << "\n";
            }
        perAssignment[t.assignment].first += t.score;
        perAssignment[t.assignment].second += t.maxScore;
    }
    out << "\n";
    for (const auto& [assignment, sum] : perAssignment)
        out << pad(assignment, nameWidth) << "  " << pad("", 11) << "  " << points(sum.first, sum.second) << "\n";
    char total[96];
    std::snprintf(total, sizeof total, "total: %.2f of %.2f points, %.1f s", report.score(), report.maxScore(), report.seconds);
    out << total << "\n";
    out << nextStepLine(report) << "\n";
}

}  // namespace rtlab::grader
