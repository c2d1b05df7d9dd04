#include "grader/kit/truth_table.h"

#include <cstdio>

namespace rtlab::grader {

std::string describeVec(const Vec3& v) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
    return buffer;
}

std::string describeBox(const Bounds3f& box) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "[(%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g)]", box.lower.x, box.lower.y, box.lower.z, box.upper.x,
                  box.upper.y, box.upper.z);
    return buffer;
}

std::string expectedGot(const std::string& expected, const std::string& got) { return "expected " + expected + ", got " + got; }

}  // namespace rtlab::grader
