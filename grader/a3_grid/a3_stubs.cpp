#include "grader/a3_grid/a3_tests.h"

namespace rtlab::grader {

const StubTable& a3Stubs() {
    static const StubTable table{"a3", "a3_grid", {
        {"grid_build.cpp", {"gridResolution", "cellOfPoint", "cellRange", "fillGridCells"}},
        {"grid_dda.cpp", {"ddaSetup", "ddaStep"}},
        {"grid_traverse.cpp", {"intersectGrid", "occludedGrid"}},
        {"two_level_grid.cpp", {"buildTwoLevelGrid", "intersectTwoLevelGrid", "occludedTwoLevelGrid"}},
    }};
    return table;
}

}  // namespace rtlab::grader
