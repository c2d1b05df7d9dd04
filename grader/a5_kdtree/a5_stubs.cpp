#include "grader/a5_kdtree/a5_tests.h"

namespace rtlab::grader {

const StubTable& a5Stubs() {
    static const StubTable table{"a5", "a5_kdtree", {
        {"bsp_autopartition.cpp", {"buildBspAutopartition", "intersectBsp", "occludedBsp"}},
        {"kd_build.cpp", {"buildKdTree"}},
        {"kd_build_nlogn.cpp", {"buildKdTreeNlogN"}},
        {"kd_events.cpp", {"kdEventBefore", "kdSortedEvents"}},
        {"kd_leaf.cpp", {"kdMaxDepth", "kdDecideNode"}},
        {"kd_sah.cpp", {"kdSahCost"}},
        {"kd_split.cpp", {"kdBestSplit", "kdClassify"}},
        {"kd_traverse.cpp", {"kdChildOrder", "intersectKdTree", "occludedKdTree"}},
    }};
    return table;
}

}  // namespace rtlab::grader
