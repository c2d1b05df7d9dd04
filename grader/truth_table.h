// Counts a truth table's cases for one graded test: the first wrong case becomes the reason,
// every wrong one a detail, and the score is the share of right cases (setFromCounts).
#pragma once

#include "grader/test_result.h"

#include <string>

namespace rtlab::grader {

class Tally {
public:
    explicit Tally(TestResult& result) : result_(result) {}

    // One case: an empty problem means it was answered right.
    void record(const std::string& id, const std::string& problem) {
        ++total_;
        if (problem.empty()) {
            ++passed_;
            return;
        }
        result_.details.push_back(id + ": " + problem);
        if (first_.empty()) first_ = id + ": " + problem;
    }
    void finish() { setFromCounts(result_, passed_, total_, first_); }

private:
    TestResult& result_;
    size_t passed_ = 0, total_ = 0;
    std::string first_;
};

}  // namespace rtlab::grader
