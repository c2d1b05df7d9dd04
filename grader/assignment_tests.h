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
std::vector<TestGroup> a4Groups(GradingContext& context);      // a4_tests.cpp
std::vector<TestGroup> a5Groups(GradingContext& context);      // a5_tests.cpp
std::vector<TestGroup> a6Groups(GradingContext& context);      // a6_tests.cpp
// The image tests of an assignment whose structure renders the scenes (image_tests.cpp).
struct ImageConfig {
    std::string assignment;   // "a1": tests named a1/images/<scene>
    std::string accelerator;  // the registry name the worker renders with: "bvh-median"
    std::string stub;         // named in verdicts
};
std::vector<TestGroup> imageGroups(GradingContext& context, const ImageConfig& config);

// The stubs named in verdicts ("crashed with SIGSEGV in <stub>").
inline constexpr const char* kStubBox = "a0 intersectBox (assignments/a0_intersect/ray_box.cpp)";
inline constexpr const char* kStubTriangle = "a0 intersectTriangle (assignments/a0_intersect/ray_triangle.cpp)";
inline constexpr const char* kStubSphere = "a0 intersectSphere (assignments/a0_intersect/ray_sphere.cpp)";

}  // namespace rtlab::grader
