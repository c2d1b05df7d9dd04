// The graded tests of each assignment (docs/grading.md, "What is tested"), as test groups the
// grading session runs in sandboxed children.
#pragma once

#include "grader/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a0Groups(GradingContext& context);      // a0_tests.cpp
std::vector<TestGroup> a1Groups(GradingContext& context);      // a1_tests.cpp
std::vector<TestGroup> a2Groups(GradingContext& context);      // a2_tests.cpp
std::vector<TestGroup> a3Groups(GradingContext& context);      // a3_tests.cpp
std::vector<TestGroup> imageGroups(GradingContext& context);   // image_tests.cpp

// The stubs named in verdicts ("crashed with SIGSEGV in <stub>").
inline constexpr const char* kStubBox = "a0 intersectBox (assignments/a0_intersect/ray_box.cpp)";
inline constexpr const char* kStubTriangle = "a0 intersectTriangle (assignments/a0_intersect/ray_triangle.cpp)";
inline constexpr const char* kStubSphere = "a0 intersectSphere (assignments/a0_intersect/ray_sphere.cpp)";

}  // namespace rtlab::grader
