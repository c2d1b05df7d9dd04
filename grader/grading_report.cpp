#include "grader/grading_report.h"

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

}  // namespace rtlab::grader
