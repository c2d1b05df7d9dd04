// The four structures on the wire, both ways: a worker's build sends its structure to the grader
// in these forms, and the grader sends its own structures (given_structure.h) to a worker's
// given-query tasks in them. Reading checks every index against the arrays it points into and
// every child link to point forward, so a decoded structure can be walked without leaving its
// arrays or looping; anything else is a WireError.
#pragma once

#include "framework/interface/bvh.h"
#include "framework/interface/grid.h"
#include "framework/interface/kdtree.h"
#include "framework/interface/octree.h"
#include "grader/wire_format.h"

namespace rtlab::grader {

void writeGrid(ByteWriter& out, const UniformGrid& grid);  // GridFrame, [u32] cellStart, [u32] primIndices
UniformGrid readGrid(ByteReader& in, uint32_t primCount);

void writeOctree(ByteWriter& out, const Octree& octree);  // Bounds3f root, [OctreeNode], [u32]
Octree readOctree(ByteReader& in, uint32_t primCount);

void writeKdTree(ByteWriter& out, const KdTree& tree);  // KdTreeFrame, [KdNode], [u32]
KdTree readKdTree(ByteReader& in, uint32_t primCount);

void writeBvh(ByteWriter& out, const Bvh& bvh);  // [BvhNode], [u32]
Bvh readBvh(ByteReader& in, uint32_t primCount);

}  // namespace rtlab::grader
