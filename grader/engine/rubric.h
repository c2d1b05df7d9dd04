// Points and visibility per test, from an instructor-edited JSON file (grader/rubric.json,
// docs/grading.md "The rubric"). Rules are tried in order; the first whose pattern matches a
// test's name applies ('*' matches any run of characters, '/' included).
#pragma once

#include "grader/engine/test_result.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace rtlab::grader {

struct RubricRule {
    std::string pattern;
    double points = 0.0;
    std::string visibility = "visible";  // Gradescope: visible, hidden, after_due_date, after_published
};

// Where a student works on a test and reads about it: the "guides" of the rubric file, matched
// like rules (first match). The terminal report's "Next:" line names them.
struct RubricGuide {
    std::string pattern;
    std::string stub;  // "assignments/a0_intersect/ray_box.cpp"
    std::string docs;  // "docs/a0-intersect.md#slab-test"
};

class Rubric {
public:
    // Throws rtlab::Error naming the file and the problem for a malformed rubric. The rules and
    // guides of each part (an assignment's grader/<folder>/rubric.json) are read first, in
    // order, then the file's; the precision is the file's.
    static Rubric load(const std::string& path, const std::vector<std::string>& parts = {});

    // Sets maxScore, score (fraction x points, rounded to precision()) and visibility of every
    // result, and its stub and docs from the first guide that matches. A test no rule matches
    // is worth 0 points (and is still reported).
    void apply(std::vector<TestResult>& results) const;

    // The results for exactly the tests the grader defines, in its order, with the rubric
    // applied: a reported result whose name is not in `defined` is dropped (a name read back
    // from a report or a worker earns nothing), a defined test nobody reported fails with
    // missingReason. Fractions are clamped to [0, 1].
    std::vector<TestResult> applyToDefined(const std::vector<TestResult>& defined, const std::vector<TestResult>& reported,
                                           const std::string& missingReason = "no result") const;

    // Decimals scores are rounded to ("precision" in the rubric file, 0..6, default 2).
    int precision() const { return precision_; }
    double round(double points) const;

private:
    void readRules(const std::string& path, const nlohmann::json& json);

    std::vector<RubricRule> rules_;
    std::vector<RubricGuide> guides_;
    int precision_ = 2;
};

bool globMatches(const std::string& pattern, const std::string& text);

}  // namespace rtlab::grader
