// Stratified samples (docs/conventions.md#sampling): n jittered samples, one in each of n
// equal strata of [0, 1) or [0, 1)^2, in a random order. Stratification keeps a pixel's samples
// from clumping, so its error falls faster than the N^-1/2 of independent samples wherever the
// integrand is smooth; the random order keeps the strata of one dimension independent of
// another's (pbrt-v3's StratifiedSampler does the same).
#pragma once

#include "framework/core/pcg32.h"
#include "framework/core/vec.h"

#include <span>

namespace rtlab {

// The largest float below 1: stratified values stay in [0, 1) whatever the rounding.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// An index uniform in [0, n), n > 0, without modulo bias (rejection of the top remainder).
uint32_t uniformIndex(Pcg32& rng, uint32_t n);

// The 2D strata of n samples: rows = the largest divisor of n not above sqrt(n), columns =
// n / rows (8 -> 4 x 2, 16 -> 4 x 4, 7 -> 7 x 1).
struct StrataGrid {
    int columns;
    int rows;
};
StrataGrid strataGrid(int n);

// Fills `out` with out.size() stratified values: stratum k holds (k + jitter) / n, then the
// values are shuffled (Fisher-Yates). Consumes 2 n random numbers of rng at most.
void stratified1D(Pcg32& rng, std::span<float> out);
// The same in 2D over strataGrid(out.size()).
void stratified2D(Pcg32& rng, std::span<Vec2> out);

}  // namespace rtlab
