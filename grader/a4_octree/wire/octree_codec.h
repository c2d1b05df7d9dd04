// An octree on the wire, both ways (as grid_codec.h): read back validated, every child block after
// its parent and inside the node list, every leaf's range inside the primitive list.
#pragma once

#include "framework/interface/octree.h"
#include "grader/wire/wire_format.h"

namespace rtlab::grader {

void writeOctree(ByteWriter& out, const Octree& octree);  // Bounds3f root, [OctreeNode], [u32]
Octree readOctree(ByteReader& in, uint32_t primCount);

}  // namespace rtlab::grader
