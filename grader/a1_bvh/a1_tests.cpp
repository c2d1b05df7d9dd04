// Assignment a1: BVH building with median, midpoint and equal-counts splits, and the three
// traversals.
#include "grader/a1_bvh/a1_tests.h"
#include "grader/kit/image_tests.h"
#include "grader/a1_bvh/bvh_tests.h"
#include "grader/a1_bvh/split_cases.h"

namespace rtlab::grader {

std::vector<TestGroup> a1Groups(GradingContext& context) {
    std::vector<TestGroup> groups;
    auto cases = a1SplitCases();
    auto only = [&](SplitFunction f) {
        std::vector<SplitCase> chosen;
        for (const SplitCase& c : cases)
            if (c.function == f) chosen.push_back(c);
        return chosen;
    };
    groups.push_back(splitCaseGroup(a1Stubs(), "a1/splits/median", only(SplitFunction::Median)));
    groups.push_back(splitCaseGroup(a1Stubs(), "a1/splits/middle", only(SplitFunction::Middle)));
    groups.push_back(splitCaseGroup(a1Stubs(), "a1/splits/equal-counts", only(SplitFunction::EqualCounts)));

    struct Method {
        const char* label;
        SplitMethod method;
        const char* function;
    };
    for (Method m : {Method{"median", SplitMethod::Median, "splitMedian"}, Method{"middle", SplitMethod::Middle, "splitMiddle"},
                     Method{"equal-counts", SplitMethod::EqualCounts, "splitEqualCounts"}}) {
        BvhConfig config;
        config.assignment = "a1";
        config.label = m.label;
        config.options.method = m.method;
        config.buildStub = a1Stubs().name("buildBvh") + " with " + a1Stubs().function(m.function);
        config.exactSah = true;
        config.recursive = true;
        config.visitOrder = m.method == SplitMethod::Median;  // once: the traversal is the same for every build
        for (TestGroup& g : bvhConfigGroups(config, context)) groups.push_back(std::move(g));
    }
    // Every scene rendered through the structure.
    for (TestGroup& g : imageGroups(context, {"a1", "bvh-median", "the renderer with --accel bvh-median (a0 + a1 functions)",
                                                a1Stubs().name("buildBvh")}))
        groups.push_back(std::move(g));
    return groups;
}

}  // namespace rtlab::grader
