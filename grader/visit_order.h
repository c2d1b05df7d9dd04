// The visit-order test of the ordered BVH traversal (docs/a1-bvh.md#traversal), judged on the
// student's own tree from the primitives it tested, in order:
//  * the first leaf entered is the first leaf a near-first walk reaches (near child: the first
//    unless the ray's direction is negative on the node's axis), which a far-first traversal
//    misses;
//  * no leaf is entered whose box starts beyond the closest hit among the primitives tested
//    before it, which a traversal that never shrinks tMax does.
// Both hold for any correct traversal whatever its float rounding: rays whose walk meets a box
// within rounding of its edge are not graded, and distances compare with a relative slack.
#pragma once

#include "framework/interface/bvh.h"
#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct VisitOrderVerdict {
    size_t graded = 0;               // rays judged (the others meet a box edge within rounding)
    size_t wrong = 0;
    std::vector<std::string> problems;  // the first few, one line each
};

// tested[i]: the primitives ray i's traversal tested, in order (cut at some length).
VisitOrderVerdict judgeVisitOrder(const Bvh& bvh, const Scene& scene, const std::vector<Ray>& rays,
                                  const std::vector<std::vector<uint32_t>>& tested);

// How many wrong rays a correct traversal may still show (primitive edges the double-precision
// oracle and a float test decide differently): 1 % of those graded, at least 2.
inline size_t allowedVisitOrderErrors(size_t graded) { return std::max<size_t>(2, graded / 100); }

}  // namespace rtlab::grader
