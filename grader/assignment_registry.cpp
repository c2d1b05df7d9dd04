#include "grader/engine/assignment_registry.h"

#include "grader/a0_intersect/a0_tests.h"
#include "grader/a1_bvh/a1_tests.h"
#include "grader/a2_sah/a2_tests.h"
#include "grader/a3_grid/a3_tests.h"
#include "grader/a4_octree/a4_tests.h"
#include "grader/a5_kdtree/a5_tests.h"
#include "grader/a6_radiometry/a6_tests.h"

// The one list of graded assignments: an assignment is its folders, its entry here and the
// entry's include (docs/adding-an-assignment.md).
namespace rtlab::grader {

const std::vector<Assignment>& assignments() {
    static const std::vector<Assignment> list{
        {"a0", "ray-box, ray-triangle and ray-sphere tests", a0Groups, a0Stubs, {"a0_intersect"}},
        {"a1", "BVH with median, middle and equal-counts splits", a1Groups, a1Stubs, {"a0_intersect", "a1_bvh"}},
        {"a2", "SAH: full sweep and buckets", a2Groups, a2Stubs, {"a0_intersect", "a1_bvh", "a2_sah"}},
        {"a3", "uniform grid and 3D-DDA", a3Groups, a3Stubs, {"a0_intersect", "a3_grid"}},
        {"a4", "octree: exact insertion and the parametric walk", a4Groups, a4Stubs, {"a0_intersect", "a4_octree"}},
        {"a5", "KD-tree: the SAH with events, the leaf rule, front-to-back traversal", a5Groups, a5Stubs, {"a0_intersect", "a5_kdtree"}},
        {"a6", "radiometry and Monte Carlo direct lighting", a6Groups, a6Stubs, {"a6_radiometry"}},
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
