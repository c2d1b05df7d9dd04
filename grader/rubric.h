// Points and visibility per test, from an instructor-edited JSON file (grader/rubric.json,
// docs/grading.md "The rubric"). Rules are tried in order; the first whose pattern matches a
// test's name applies ('*' matches any run of characters, '/' included).
#pragma once

#include "grader/test_result.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct RubricRule {
    std::string pattern;
    double points = 0.0;
    std::string visibility = "visible";  // Gradescope: visible, hidden, after_due_date, after_published
};

class Rubric {
public:
    // Throws rtlab::Error naming the file and the problem for a malformed rubric.
    static Rubric load(const std::string& path);

    // Sets maxScore, score (fraction x points) and visibility of every result. A test no rule
    // matches is worth 0 points (and is still reported).
    void apply(std::vector<TestResult>& results) const;

private:
    std::vector<RubricRule> rules_;
};

bool globMatches(const std::string& pattern, const std::string& text);

}  // namespace rtlab::grader
