// The checks every structure's decoder makes before a traversal may walk what it read
// (grader/<assignment>/wire/*_codec.cpp): primitive ids within the scene, leaf ranges within
// the primitive list, and the size of a list bounded.
#pragma once

#include "grader/wire/wire_format.h"

#include <cstdint>
#include <vector>

namespace rtlab::grader {

// Larger than any structure the graded scenes give (a 64^3 grid holds 262,145 cell starts).
inline constexpr uint64_t kMaxStructureEntries = uint64_t(1) << 26;

inline void checkPrimitiveIds(const std::vector<uint32_t>& prims, uint32_t primCount) {
    for (uint32_t p : prims)
        if (p >= primCount) throw WireError("a primitive id out of range");
}

inline void checkLeafRange(uint64_t start, uint64_t count, size_t size) {
    if (start > size || count > size - start) throw WireError("a leaf's range beyond the primitive list");
}

}  // namespace rtlab::grader
