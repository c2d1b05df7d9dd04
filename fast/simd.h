// Portable SIMD values: GCC's vector extensions. Simd<float, 4> is four floats in one register;
// +, -, *, /, comparisons and ?: work lane by lane, and a comparison gives a mask of -1 (true)
// or 0 per lane. The compiler picks the instructions for the target: SSE or NEON for 16 bytes,
// one AVX register for 32 bytes with -mavx or -march=native (two 16-byte halves without).
//
// Lane arithmetic is IEEE arithmetic, so a lane computes exactly what the same scalar
// expression computes; the wide BVH relies on that to report the scalar tests' hits bit for bit.
#pragma once

#include "fast/isa.h"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

namespace rtlab {
RTLAB_ISA_NAMESPACE_BEGIN

template <typename T, int N>
struct SimdVector {
    typedef T type __attribute__((vector_size(N * sizeof(T))));
};

template <typename T, int N>
using Simd = typename SimdVector<T, N>::type;

// The integer vector a comparison of Simd<float, N> returns.
template <int N>
using SimdMask = Simd<int32_t, N>;

// {0, 1, ..., N - 1}: each lane's index, as a constant.
template <int N, size_t... I>
constexpr SimdMask<N> laneIndicesOf(std::index_sequence<I...>) {
    return SimdMask<N>{int32_t(I)...};
}
template <int N>
constexpr SimdMask<N> laneIndices() {
    return laneIndicesOf<N>(std::make_index_sequence<N>{});
}

template <int N>
Simd<float, N> broadcast(float value) {
    return value - Simd<float, N>{};
}

template <int N>
Simd<float, N> load(const float (&values)[N]) {
    Simd<float, N> lanes;
    std::memcpy(&lanes, values, sizeof lanes);
    return lanes;
}

// Bit i set when lane i of the mask is true: one MOVMSKPS on x86 (GCC does not turn the
// portable loop into it), a loop elsewhere.
template <int N>
unsigned laneBits(SimdMask<N> mask) {
#if defined(__AVX__)
    if constexpr (N == 8) return static_cast<unsigned>(__builtin_ia32_movmskps256(std::bit_cast<Simd<float, 8>>(mask)));
#endif
#if defined(__SSE__)
    if constexpr (N == 4) return static_cast<unsigned>(__builtin_ia32_movmskps(std::bit_cast<Simd<float, 4>>(mask)));
#endif
    int32_t lanes[N];
    std::memcpy(lanes, &mask, sizeof lanes);
    unsigned bits = 0;
    for (int i = 0; i < N; ++i) bits |= (lanes[i] & 1u) << i;
    return bits;
}

// The value as it stands, rounded: the compiler cannot fuse the operation that made it into the
// next one (FMA contraction, which GCC does by default wherever the target has FMA), because an
// empty asm statement it cannot see through holds it in a register. Elsewhere a volatile copy
// does the same at the cost of a store and a load.
template <typename V>
V roundedAsIs(V value) {
#if defined(__x86_64__) || defined(__i386__)
    asm("" : "+x"(value));
#elif defined(__aarch64__)
    asm("" : "+w"(value));
#else
    volatile V copy = value;
    value = copy;
#endif
    return value;
}

// -value, broadcast to N lanes, for writing p - value as p + negated: the same IEEE operation
// (x - y is defined as x + (-y)), signed zeros and NaNs included. An addition takes its
// memory operand on either side, so an AVX build folds the row's load into it; SUBPS can take
// only the subtrahend from memory. The negation is made opaque: GCC would turn x + (-y) back
// into x - y.
template <int N>
Simd<float, N> broadcastNegated(float value) {
    return broadcast<N>(roundedAsIs(-value));
}

RTLAB_ISA_NAMESPACE_END
}  // namespace rtlab
