// The visit-order test of the octree traversal (docs/a4-octree.md#how-the-grader-checks-it),
// judged on the student's own octree (one that passed the structure check) from the leaves its
// closest-hit walk entered, in order, against an exact oracle: the leaves whose closed boxes
// the ray's segment [tMin, tMax] crosses, sorted by where the ray enters them (in double), up
// to the first one after which the closest hit among the leaves so far lies no farther than
// where the ray leaves it. Rays whose answer rounding may change are not graded: those passing
// within rounding of a leaf's edge or corner, or along a face, entering two leaves at nearly
// the same t, meeting a leaf's end within rounding of the segment's ends or of the closest
// hit, or hitting a triangle within rounding of its edge.
#pragma once

#include "framework/interface/octree.h"
#include "framework/scene/scene.h"
#include "grader/kit/visit_order_verdict.h"

#include <optional>
#include <vector>

namespace rtlab::grader {

// entered[i]: the leaves ray i's traversal entered, in order (cut at some length).
VisitOrderVerdict judgeOctreeVisits(const Octree& octree, const Scene& scene, const std::vector<Ray>& rays,
                                    const std::vector<std::vector<uint32_t>>& entered);

// The exact leaf sequence of one ray, or nullopt when the ray is not graded (see above).
std::optional<std::vector<uint32_t>> expectedLeafOrder(const Octree& octree, const std::vector<Bounds3f>& nodeBoxes,
                                                       const Scene& scene, const Ray& ray);

// Every node's box, from the root by the contract's childBox.
std::vector<Bounds3f> octreeNodeBoxes(const Octree& octree);

}  // namespace rtlab::grader
