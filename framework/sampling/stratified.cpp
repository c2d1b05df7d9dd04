#include "framework/sampling/stratified.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rtlab {
namespace {

template <typename T>
void shuffle(Pcg32& rng, std::span<T> values) {
    for (size_t i = values.size(); i > 1; --i) std::swap(values[i - 1], values[uniformIndex(rng, static_cast<uint32_t>(i))]);
}

float jittered(int stratum, int count, Pcg32& rng) {
    return std::min((static_cast<float>(stratum) + rng.uniform()) / static_cast<float>(count), kOneMinusEpsilon);
}

}  // namespace

uint32_t uniformIndex(Pcg32& rng, uint32_t n) {
    // 2^32 mod n values at the bottom would make the low indices more likely: draw again.
    uint32_t threshold = (0u - n) % n;
    for (;;) {
        uint32_t r = rng.next();
        if (r >= threshold) return r % n;
    }
}

StrataGrid strataGrid(int n) {
    int rows = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
    while (n % rows != 0) --rows;
    return {n / rows, rows};
}

void stratified1D(Pcg32& rng, std::span<float> out) {
    int n = static_cast<int>(out.size());
    for (int k = 0; k < n; ++k) out[k] = jittered(k, n, rng);
    shuffle(rng, out);
}

void stratified2D(Pcg32& rng, std::span<Vec2> out) {
    StrataGrid grid = strataGrid(static_cast<int>(out.size()));
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            float x = jittered(column, grid.columns, rng);
            out[row * grid.columns + column] = Vec2(x, jittered(row, grid.rows, rng));
        }
    shuffle(rng, out);
}

}  // namespace rtlab
