// What the truth-table tests share (a3, a4 and a5): counting the cases of one test, and
// printing the vectors their inputs and answers are made of.
#pragma once

#include "framework/core/bounds.h"
#include "grader/test_result.h"

#include <string>

namespace rtlab::grader {

// Counts a truth table's cases; the first wrong one becomes the reason, every one a detail.
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

// "(x, y, z)" with every float's shortest exact digits (9 significant).
std::string describeVec(const Vec3& v);
// "[(x, y, z), (x, y, z)]".
std::string describeBox(const Bounds3f& box);

}  // namespace rtlab::grader
