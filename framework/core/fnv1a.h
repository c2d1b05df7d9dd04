// FNV-1a, 64 bit (Fowler, Noll, Vo): a tiny hash over raw bytes, used to fingerprint the
// procedural benchmark scenes and ray sets so that any change of their bits is noticed.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rtlab {

inline constexpr uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;
inline constexpr uint64_t kFnv1aPrime = 0x100000001b3ull;

// Continues the hash `hash` over size bytes at data (start with kFnv1aOffsetBasis).
inline uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = kFnv1aOffsetBasis) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= kFnv1aPrime;
    }
    return hash;
}

}  // namespace rtlab
