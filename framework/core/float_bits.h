// Floating-point helpers for robust geometry (pbrt-v4, "Managing Rounding Error").
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rtlab {

// Half an ulp of 1.0f: the unit roundoff u of IEEE single precision.
inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;

// gamma(n) = n u / (1 - n u) bounds the relative error of n successive float operations.
constexpr float gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

// a*b - c*d rounded once, with the exact sign. The product of two floats is exact in double
// (24 + 24 bits fit in 53), so the difference is the exact value rounded once: its sign is
// right, it is zero only when a*b == c*d, and swapping the pairs negates it exactly. That is
// what keeps edge functions watertight, and it holds whether or not the compiler fuses
// multiply-adds (fusing an exact product changes nothing). pbrt-v4 gets the same guarantee in
// float with Kahan's FMA algorithm; without hardware FMA that algorithm calls libm's fmaf.
inline float differenceOfProducts(float a, float b, float c, float d) {
    return static_cast<float>(static_cast<double>(a) * b - static_cast<double>(c) * d);
}

inline float nextFloatUp(float v) {
    if (std::isinf(v) && v > 0) return v;
    if (v == -0.0f) v = 0.0f;
    uint32_t bits = std::bit_cast<uint32_t>(v);
    bits = v >= 0 ? bits + 1 : bits - 1;
    return std::bit_cast<float>(bits);
}

inline float nextFloatDown(float v) {
    if (std::isinf(v) && v < 0) return v;
    if (v == 0.0f) v = -0.0f;
    uint32_t bits = std::bit_cast<uint32_t>(v);
    bits = v > 0 ? bits - 1 : bits + 1;
    return std::bit_cast<float>(bits);
}

// nextFloatUp(v) when direction > 0, nextFloatDown(v) when direction < 0, v otherwise (zero or
// NaN), bit for bit, with every choice a select instead of a branch. Where a shadow ray leaves a
// surface, the signs of the offset and of the point change from pixel to pixel, and the
// branches of the two functions above mispredicted there more often than not.
inline float floatStep(float v, float direction) {
    const uint32_t bits = std::bit_cast<uint32_t>(v);
    const bool zero = v == 0.0f;
    // Up: -0 counts as +0; a non-negative float grows by one in its bits, a negative one shrinks.
    const uint32_t fromUp = zero ? 0u : bits;
    const uint32_t up = v == std::numeric_limits<float>::infinity() ? bits : (v >= 0.0f ? fromUp + 1 : fromUp - 1);
    // Down: +0 counts as -0, and the other way round.
    const uint32_t fromDown = zero ? 0x80000000u : bits;
    const uint32_t down = v == -std::numeric_limits<float>::infinity() ? bits : (v > 0.0f ? fromDown - 1 : fromDown + 1);
    const uint32_t stepped = direction > 0.0f ? up : (direction < 0.0f ? down : bits);
    return std::bit_cast<float>(stepped);
}

}  // namespace rtlab
