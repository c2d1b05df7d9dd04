#include "grader/rubric.h"

#include "framework/core/error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace rtlab::grader {

bool globMatches(const std::string& pattern, const std::string& text) {
    size_t p = 0, t = 0, star = std::string::npos, resume = 0;
    while (t < text.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = t;
        } else if (p < pattern.size() && pattern[p] == text[t]) {
            ++p;
            ++t;
        } else if (star != std::string::npos) {
            p = star + 1;
            t = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

Rubric Rubric::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot read the rubric");
    Rubric rubric;
    try {
        auto json = nlohmann::json::parse(in);
        for (const auto& rule : json.at("rules")) {
            RubricRule r{rule.at("match").get<std::string>(), rule.at("points").get<double>(), rule.value("visibility", "visible")};
            if (r.visibility != "visible" && r.visibility != "hidden" && r.visibility != "after_due_date" &&
                r.visibility != "after_published")
                throw Error(path + ": rule \"" + r.pattern + "\" has visibility \"" + r.visibility +
                            "\" (valid: visible, hidden, after_due_date, after_published)");
            if (!(r.points >= 0)) throw Error(path + ": rule \"" + r.pattern + "\" has negative points");
            rubric.rules_.push_back(r);
        }
    } catch (const nlohmann::json::exception& e) {
        throw Error(path + ": malformed rubric (" + e.what() + ")");
    }
    return rubric;
}

void Rubric::apply(std::vector<TestResult>& results) const {
    for (TestResult& result : results) {
        result.maxScore = 0.0;
        for (const RubricRule& rule : rules_)
            if (globMatches(rule.pattern, result.name)) {
                result.maxScore = rule.points;
                result.visibility = rule.visibility;
                break;
            }
        // Rounded to 1/100 point so reports add up to what they print.
        result.score = std::round(100.0 * result.maxScore * result.fraction) / 100.0;
    }
}

}  // namespace rtlab::grader
