#include "grader/engine/grading_report.h"

#include "framework/core/untrusted_text.h"

#include <cmath>

namespace rtlab::grader {

namespace {

// Test scores have at most 6 decimals (the rubric's precision is 0..6), so their exact sum has
// at most 6 too: rounding there removes only the binary floating-point noise of the additions
// (0.1 + 0.2), and a total of 300 reads 300 in JSON, not 300.00000000000006.
double decimalSum(const std::vector<TestResult>& tests, double TestResult::*field) {
    double sum = 0.0;
    for (const TestResult& t : tests) sum += t.*field;
    return std::round(sum * 1e6) / 1e6;
}

}  // namespace

double GradingReport::score() const { return decimalSum(tests, &TestResult::score); }

double GradingReport::maxScore() const { return decimalSum(tests, &TestResult::maxScore); }

std::string testOutput(const TestResult& test) {
    std::string text = test.reason;
    for (const std::string& line : test.details) text += (text.empty() ? "" : "\n") + line;
    return text;
}

GradingReport displaySafe(const GradingReport& report) {
    auto line = [](const std::string& text) { return escapeUntrusted(text, TextLayout::OneLine); };
    GradingReport safe = report;
    safe.implementation = line(report.implementation);
    safe.studentOutput = escapeUntrusted(report.studentOutput, TextLayout::Lines);
    safe.isolation = escapeUntrusted(report.isolation, TextLayout::Lines);
    for (TestResult& t : safe.tests) {
        t.assignment = line(t.assignment);
        t.name = line(t.name);
        t.reason = line(t.reason);
        t.visibility = line(t.visibility);
        t.stub = line(t.stub);
        t.docs = line(t.docs);
        for (std::string& d : t.details) d = line(d);
        for (ReportImage& image : t.images) image.label = line(image.label);
        for (FailedCase& c : t.failedCases) {
            c.title = line(c.title);
            for (std::string& n : c.notes) n = line(n);
            for (CaseRay& r : c.rays) r.label = line(r.label);
        }
    }
    return safe;
}

}  // namespace rtlab::grader
