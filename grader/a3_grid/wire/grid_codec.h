// A uniform grid on the wire, both ways: the worker's build sends it to the grader, the grader sends
// its own grid to the given-query task (grader/kit/given_structure.h). Read back validated: cell
// starts one per cell plus one, rising, ending at the list's size; primitive ids in range.
#pragma once

#include "framework/interface/grid.h"
#include "grader/wire/wire_format.h"

namespace rtlab::grader {

void writeGrid(ByteWriter& out, const UniformGrid& grid);  // GridFrame, [u32] cellStart, [u32] primIndices
UniformGrid readGrid(ByteReader& in, uint32_t primCount);

}  // namespace rtlab::grader
