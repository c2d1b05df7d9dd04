#include "grader/a0_intersect/a0_tests.h"

namespace rtlab::grader {

const StubTable& a0Stubs() {
    static const StubTable table{"a0", "a0_intersect", {
        {"ray_box.cpp", {"intersectBox"}},
        {"ray_sphere.cpp", {"intersectSphere"}},
        {"ray_triangle.cpp", {"intersectTriangle"}},
    }};
    return table;
}

}  // namespace rtlab::grader
