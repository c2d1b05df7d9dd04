// The grader's own structures for the given-structure queries (given_structure.h): built over a
// scene by simple rules of the grader's (they need not be the assignments' pinned rules, only
// structures the traversal contracts accept), with primitives left out of leaves by key, and
// encoded for the worker's given-query tasks (structure_codec.h). One file each.
#pragma once

#include "framework/scene/scene.h"
#include "grader/given_structure.h"

#include <cstdint>

namespace rtlab::grader {

GivenStructure givenGrid(const Scene& scene, uint64_t key);    // given_grid.cpp: the lecture's C = 27
GivenStructure givenOctree(const Scene& scene, uint64_t key);  // given_octree.cpp: box insertion, 8 per leaf
GivenStructure givenKdTree(const Scene& scene, uint64_t key);  // given_kdtree.cpp: spatial median planes
GivenStructure givenBvh(const Scene& scene, uint64_t key);     // given_bvh.cpp: centroid median splits

}  // namespace rtlab::grader
