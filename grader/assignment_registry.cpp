#include "grader/assignment_registry.h"

#include "grader/assignment_tests.h"

namespace rtlab::grader {
namespace {

// a1 also owns the image tests: they render through the student's BVH.
std::vector<TestGroup> a1AndImageGroups(GradingContext& context) {
    std::vector<TestGroup> groups = a1Groups(context);
    for (TestGroup& g : imageGroups(context)) groups.push_back(std::move(g));
    return groups;
}

}  // namespace

const std::vector<Assignment>& assignments() {
    static const std::vector<Assignment> list{
        {"a0", "ray-box, ray-triangle and ray-sphere tests", a0Groups},
        {"a1", "BVH with median, middle and equal-counts splits", a1AndImageGroups},
        {"a2", "SAH: full sweep and buckets", a2Groups},
        {"a3", "uniform grid and 3D-DDA", a3Groups},
    };
    return list;
}

const Assignment* findAssignment(const std::string& id) {
    for (const Assignment& a : assignments())
        if (a.id == id) return &a;
    return nullptr;
}

std::string assignmentIds() {
    std::string ids;
    for (const Assignment& a : assignments()) ids += (ids.empty() ? "" : ", ") + a.id;
    return ids;
}

}  // namespace rtlab::grader
