// The grader's own structure for the given-structure queries (grader/kit/given_structure.h):
// centroid median splits, at most 4 primitives a leaf; built by the grader's simple rules (not the assignment's pinned ones: any structure
// the traversal's contract accepts will do), primitives left out of leaves by key, encoded for
// the worker's given-query task (grader/a1_bvh/wire/bvh_codec.h).
#pragma once

#include "framework/scene/scene.h"
#include "grader/kit/given_structure.h"

#include <cstdint>

namespace rtlab::grader {

GivenStructure givenBvh(const Scene& scene, uint64_t key);

}  // namespace rtlab::grader
