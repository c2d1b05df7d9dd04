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
#include "grader/kit/visit_order_verdict.h"

#include <string>
#include <vector>

namespace rtlab::grader {

// tested[i]: the primitives ray i's traversal tested, in order (cut at some length).
VisitOrderVerdict judgeVisitOrder(const Bvh& bvh, const Scene& scene, const std::vector<Ray>& rays,
                                  const std::vector<std::vector<uint32_t>>& tested);

}  // namespace rtlab::grader
