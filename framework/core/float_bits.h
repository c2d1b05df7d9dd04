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

// a*b - c*d with about 1.5 ulp error and the exact sign (Kahan's algorithm). Stays exact in sign
// whether or not the compiler contracts into FMA, which keeps edge functions watertight.
inline float differenceOfProducts(float a, float b, float c, float d) {
    float cd = c * d;
    float difference = std::fma(a, b, -cd);
    float error = std::fma(-c, d, cd);
    return difference + error;
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

}  // namespace rtlab
