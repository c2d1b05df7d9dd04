#include "grader/assignment_registry.h"

#include "grader/assignment_tests.h"

namespace rtlab::grader {
namespace {

// An assignment's groups followed by its image tests, rendered through its structure.
template <std::vector<TestGroup> (*groupsOf)(GradingContext&)>
std::vector<TestGroup> withImages(GradingContext& context, const ImageConfig& images) {
    std::vector<TestGroup> groups = groupsOf(context);
    for (TestGroup& g : imageGroups(context, images)) groups.push_back(std::move(g));
    return groups;
}

std::vector<TestGroup> a1WithImages(GradingContext& context) {
    return withImages<a1Groups>(context, {"a1", "bvh-median", "the renderer with --accel bvh-median (a0 + a1 functions)"});
}

std::vector<TestGroup> a3WithImages(GradingContext& context) {
    return withImages<a3Groups>(context, {"a3", "grid", "the renderer with --accel grid (a0 + a3 functions)"});
}

std::vector<TestGroup> a4WithImages(GradingContext& context) {
    return withImages<a4Groups>(context, {"a4", "octree", "the renderer with --accel octree (a0 + a4 functions)"});
}

std::vector<TestGroup> a5WithImages(GradingContext& context) {
    return withImages<a5Groups>(context, {"a5", "kdtree:build=sort", "the renderer with --accel kdtree:build=sort (a0 + a5 functions)"});
}

}  // namespace

const std::vector<Assignment>& assignments() {
    static const std::vector<Assignment> list{
        {"a0", "ray-box, ray-triangle and ray-sphere tests", a0Groups, {"a0_intersect"}},
        {"a1", "BVH with median, middle and equal-counts splits", a1WithImages, {"a0_intersect", "a1_bvh"}},
        {"a2", "SAH: full sweep and buckets", a2Groups, {"a0_intersect", "a1_bvh", "a2_sah"}},
        {"a3", "uniform grid and 3D-DDA", a3WithImages, {"a0_intersect", "a3_grid"}},
        {"a4", "octree: exact insertion and the parametric walk", a4WithImages, {"a0_intersect", "a4_octree"}},
        {"a5", "KD-tree: the SAH with events, the leaf rule, front-to-back traversal", a5WithImages, {"a0_intersect", "a5_kdtree"}},
        {"a6", "radiometry and Monte Carlo direct lighting", a6Groups, {"a6_radiometry"}},
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
