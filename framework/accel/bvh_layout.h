// Whether a BVH keeps the layout its traversal relies on (framework/interface/bvh.h), checked
// before any traversal of a tree that student code built. A tree that breaks it (a child index
// kept across push_back, a second child that points back up) would send a correct traversal
// round a cycle until a time limit stops it, or out of the arrays; the grader names the broken
// node instead and does not start the walk.
#pragma once

#include "framework/interface/bvh.h"

#include <cstddef>
#include <string>

namespace rtlab {

// The first rule the tree breaks, in one line naming the node, or "" when it keeps them all:
// every node reachable from the root is reached once; an interior node's children come after it
// and inside the array (the first right after it); a leaf's range lies inside primIndices and
// lists primitives below primitiveCount. Linear in the nodes reachable from the root.
std::string bvhLayoutProblem(const Bvh& bvh, size_t primitiveCount);

}  // namespace rtlab
