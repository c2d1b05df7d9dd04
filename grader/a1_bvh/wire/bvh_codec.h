// A BVH on the wire, both ways (as grid_codec.h): read back validated, first child next and second
// child later (links point forward), every leaf's range inside the primitive list.
#pragma once

#include "framework/interface/bvh.h"
#include "grader/wire/wire_format.h"

namespace rtlab::grader {

void writeBvh(ByteWriter& out, const Bvh& bvh);  // [BvhNode], [u32]
Bvh readBvh(ByteReader& in, uint32_t primCount);

}  // namespace rtlab::grader
