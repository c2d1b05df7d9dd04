// The grader's own structure for the given-structure queries (grader/kit/given_structure.h):
// box insertion, 8 primitives a leaf, depth 8; built by the grader's simple rules (not the assignment's pinned ones: any structure
// the traversal's contract accepts will do), primitives left out of leaves by key, encoded for
// the worker's given-query task (grader/a4_octree/wire/octree_codec.h).
#pragma once

#include "framework/scene/scene.h"
#include "grader/kit/given_structure.h"

#include <cstdint>

namespace rtlab::grader {

GivenStructure givenOctree(const Scene& scene, uint64_t key);

}  // namespace rtlab::grader
