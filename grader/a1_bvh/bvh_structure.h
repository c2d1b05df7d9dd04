// The grader's own reading of a BVH a child sent back (docs/grading.md, "Structure"): the
// invariants every correct build satisfies, and the SAH cost recomputed from the nodes, in
// double, without calling anything a student wrote.
#pragma once

#include "framework/core/bounds.h"
#include "framework/interface/bvh.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct BvhStructureReport {
    std::vector<std::string> problems;  // empty when every invariant holds (first few only)
    size_t problemCount = 0;
    size_t leaves = 0;
    int depth = 0;
};

// Checks: the pinned depth-first layout (first child next, second child at offset, inside the
// array, no node reachable twice or never), every primitive in exactly one leaf, every node's
// box containing its children and primitives, and, when checkTight, boxes exactly equal to
// the union of what they hold. primBounds[i] is primitive i's box.
BvhStructureReport checkBvhStructure(const Bvh& bvh, const std::vector<Bounds3f>& primBounds, bool checkTight);

// The leaf rule every method shares (docs/a1-bvh.md, "When is a node a leaf?"): a leaf holds
// more than maxLeaf primitives only when their centroids coincide or the depth cap made it (or
// when it could not hold them all: 65535 is split further anyway). A problem line per leaf
// that breaks it (the first few). Only meaningful for a BVH that passed checkBvhStructure.
std::vector<std::string> oversizedLeaves(const Bvh& bvh, const std::vector<Bounds3f>& primBounds, int maxLeaf);

// SAH cost C = sum over interior nodes of C_trav S(n)/S(root) + sum over leaves of
// N C_isect S(n)/S(root), C_trav = C_isect = 1, areas in double. A root of zero area costs N.
// Only meaningful for a BVH that passed checkBvhStructure.
double graderSahCost(const Bvh& bvh);

}  // namespace rtlab::grader
