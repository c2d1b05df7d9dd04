#include "grader/a4_octree/a4_tests.h"

namespace rtlab::grader {

const StubTable& a4Stubs() {
    static const StubTable table{"a4", "a4_octree", {
        {"octree_build.cpp", {"octreeRootBox", "childBox", "childIndex", "buildOctree"}},
        {"octree_traverse.cpp", {"intersectOctree", "occludedOctree"}},
        {"octree_walk.cpp", {"mirrorRay", "rootSpan", "midParameters", "firstNode", "nextNode"}},
        {"triangle_box.cpp", {"triangleOverlapsBox"}},
    }};
    return table;
}

}  // namespace rtlab::grader
