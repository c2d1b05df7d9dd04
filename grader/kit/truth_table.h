// How the truth-table tests of a3, a4 and a5 print the vectors their inputs and answers are
// made of (CaseTally in test_result.h counts their cases).
#pragma once

#include "framework/core/bounds.h"
#include "grader/engine/test_result.h"

#include <string>

namespace rtlab::grader {

// "(x, y, z)" with every float's shortest exact digits (9 significant).
std::string describeVec(const Vec3& v);
// "[(x, y, z), (x, y, z)]".
std::string describeBox(const Bounds3f& box);

}  // namespace rtlab::grader
