#include "grader/engine/rubric.h"

#include "framework/core/error.h"
#include "grader/engine/json_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

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

namespace {

// Text from the file, quoted and escaped as JSON, so that a message about it stays on one line.
std::string asJsonString(const std::string& text) {
    return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json readRubricFile(const std::string& path) { return readJsonFile(path, "rubric", "cannot read the rubric"); }

}  // namespace

void Rubric::readRules(const std::string& path, const nlohmann::json& json) {
    try {
        for (const auto& rule : json.at("rules")) {
            RubricRule r{rule.at("match").get<std::string>(), rule.at("points").get<double>(), rule.value("visibility", "visible")};
            if (r.visibility != "visible" && r.visibility != "hidden" && r.visibility != "after_due_date" &&
                r.visibility != "after_published")
                throw Error(path + ": rule " + asJsonString(r.pattern) + " has visibility " + asJsonString(r.visibility) +
                            " (valid: visible, hidden, after_due_date, after_published)");
            if (!(r.points >= 0)) throw Error(path + ": rule " + asJsonString(r.pattern) + " has negative points");
            rules_.push_back(r);
        }
        for (const auto& guide : json.value("guides", nlohmann::json::array()))
            guides_.push_back({guide.at("match").get<std::string>(), guide.value("stub", ""), guide.value("docs", "")});
    } catch (const nlohmann::json::exception& e) {
        throw Error(path + ": malformed rubric (" + e.what() + ")");
    }
}

Rubric Rubric::load(const std::string& path, const std::vector<std::string>& parts) {
    Rubric rubric;
    for (const std::string& part : parts) rubric.readRules(part, readRubricFile(part));
    nlohmann::json json = readRubricFile(path);
    rubric.readRules(path, json);
    if (json.contains("precision")) {
        const auto& precision = json.at("precision");
        // Compared as a 64-bit number: get<int>() would read 4294967298 as 2.
        if (!precision.is_number_integer() || precision.get<int64_t>() < 0 || precision.get<int64_t>() > 6)
            throw Error(path + ": \"precision\" must be a whole number of decimals from 0 to 6");
        rubric.precision_ = static_cast<int>(precision.get<int64_t>());
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
        result.score = round(result.maxScore * result.fraction);
        for (const RubricGuide& guide : guides_)
            if (globMatches(guide.pattern, result.name)) {
                result.stub = guide.stub;
                result.docs = guide.docs;
                break;
            }
    }
}

// Rounded so that reports and CSVs add up to what they print.
double Rubric::round(double points) const {
    double scale = std::pow(10.0, precision_);
    return std::round(points * scale) / scale;
}

std::vector<TestResult> Rubric::applyToDefined(const std::vector<TestResult>& defined, const std::vector<TestResult>& reported,
                                               const std::string& missingReason) const {
    std::map<std::string, const TestResult*> byName;
    for (const TestResult& r : reported) byName.try_emplace(r.name, &r);
    std::vector<TestResult> results;
    for (const TestResult& d : defined) {
        auto it = byName.find(d.name);
        if (it == byName.end()) {
            TestResult missing = d;
            missing.status = TestStatus::Failed;
            missing.fraction = 0.0;
            missing.reason = missingReason;
            missing.details.clear();
            missing.images.clear();
            results.push_back(missing);
            continue;
        }
        TestResult r = *it->second;
        r.assignment = d.assignment;
        r.fraction = std::isfinite(r.fraction) ? std::clamp(r.fraction, 0.0, 1.0) : 0.0;
        if (r.status == TestStatus::Passed && r.fraction < 1.0) r.status = TestStatus::Failed;
        results.push_back(r);
    }
    apply(results);
    return results;
}

}  // namespace rtlab::grader
