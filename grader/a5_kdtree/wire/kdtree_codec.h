// A KD-tree on the wire, both ways (as grid_codec.h): read back validated, below child next and
// above child later (links point forward), no node deeper than the tree's limit, which a
// traversal sizes its stack by, every leaf's range inside the primitive list.
#pragma once

#include "framework/interface/kdtree.h"
#include "grader/wire/wire_format.h"

namespace rtlab::grader {

void writeKdTree(ByteWriter& out, const KdTree& tree);  // KdTreeFrame, [KdNode], [u32]
KdTree readKdTree(ByteReader& in, uint32_t primCount);

}  // namespace rtlab::grader
