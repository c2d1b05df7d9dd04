#include "grader/grading_report.h"

#include "grader/untrusted_text.h"

namespace rtlab::grader {

double GradingReport::score() const {
    double sum = 0.0;
    for (const TestResult& t : tests) sum += t.score;
    return sum;
}

double GradingReport::maxScore() const {
    double sum = 0.0;
    for (const TestResult& t : tests) sum += t.maxScore;
    return sum;
}

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
        for (std::string& d : t.details) d = line(d);
        for (ReportImage& image : t.images) image.label = line(image.label);
    }
    return safe;
}

}  // namespace rtlab::grader
