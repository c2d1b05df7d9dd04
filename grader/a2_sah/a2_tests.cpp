// Assignment a2: the surface area heuristic, full sweep and buckets.
#include "grader/a2_sah/a2_tests.h"
#include "grader/a1_bvh/bvh_tests.h"
#include "grader/a1_bvh/split_cases.h"

namespace rtlab::grader {

std::vector<TestGroup> a2Groups(GradingContext& context) {
    std::vector<TestGroup> groups;
    std::vector<SplitCase> sweep, buckets;
    for (const SplitCase& c : a2SplitCases()) (c.function == SplitFunction::SahSweep ? sweep : buckets).push_back(c);
    groups.push_back(splitCaseGroup("a2", "a2/splits/sweep", sweep));
    groups.push_back(splitCaseGroup("a2", "a2/splits/buckets", buckets));

    struct Variant {
        const char* label;
        SplitMethod method;
        int buckets;
        bool allAxes;
    };
    for (Variant v : {Variant{"sweep", SplitMethod::SahSweep, 12, false}, Variant{"sweep-all-axes", SplitMethod::SahSweep, 12, true},
                      Variant{"buckets-4", SplitMethod::SahBuckets, 4, false}, Variant{"buckets-12", SplitMethod::SahBuckets, 12, false},
                      Variant{"buckets-32", SplitMethod::SahBuckets, 32, false},
                      Variant{"buckets-12-all-axes", SplitMethod::SahBuckets, 12, true}}) {
        BvhConfig config;
        config.assignment = "a2";
        config.label = v.label;
        config.options.method = v.method;
        config.options.buckets = v.buckets;
        config.options.allAxes = v.allAxes;
        config.buildStub = std::string("a1 buildBvh with a2 ") + (v.method == SplitMethod::SahSweep ? "splitSahSweep" : "splitSahBuckets");
        for (TestGroup& g : bvhConfigGroups(config, context)) groups.push_back(std::move(g));
    }
    return groups;
}

}  // namespace rtlab::grader
