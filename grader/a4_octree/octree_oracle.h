// The grader's own answers for a4's pinned rules (framework/interface/a4_octree.h), written from
// the contract without calling anything a student wrote: the root cube, the child boxes, and
// whether a triangle overlaps a box, decided in double on the box grown and shrunk by a slack
// so that a pair float rounding may decide either way is told apart from a sure one.
#pragma once

#include "framework/core/bounds.h"

#include <array>

namespace rtlab::grader {

enum class Overlap { No, Yes, Unsure };

// The distance within which float rounding may move a triangle-box contact, for boxes and
// triangles around `scale`: 1e-5 of the largest of the box's size and its coordinates.
double overlapSlack(const Bounds3f& box);

// The separating-axis test in double (the 13 axes, inclusive) on the box grown by slack (No
// when even that one is separated) and shrunk by it (Yes when even that one overlaps). A
// triangle with a NaN vertex never overlaps.
Overlap triangleBoxOverlap(const std::array<Vec3, 3>& triangle, const Bounds3f& box, double slack);
// Exact: closed boxes overlap when lower <= other.upper and upper >= other.lower per axis.
bool boxesOverlap(const Bounds3f& a, const Bounds3f& b);

// The root cube of the contract (octreeRootBox) and the child boxes (childBox).
Bounds3f expectedRootBox(const Bounds3f& bounds);
Bounds3f expectedChildBox(const Bounds3f& box, int child);

}  // namespace rtlab::grader
