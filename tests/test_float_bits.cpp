// The float-step helpers the secondary rays are offset with: floatStep, the select-only form
// the renderer uses, is nextFloatUp and nextFloatDown bit for bit, on the floats where they
// have a rule of their own (zeros, the smallest and largest, infinities, NaN) and on random bit
// patterns of every exponent.
#include "framework/core/float_bits.h"
#include "framework/core/pcg32.h"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>

using namespace rtlab;

namespace {

uint32_t bitsOf(float v) { return std::bit_cast<uint32_t>(v); }

void checkStep(float v) {
    CAPTURE(bitsOf(v));
    CHECK(bitsOf(floatStep(v, 1.0f)) == bitsOf(nextFloatUp(v)));
    CHECK(bitsOf(floatStep(v, -1.0f)) == bitsOf(nextFloatDown(v)));
    CHECK(bitsOf(floatStep(v, 0.0f)) == bitsOf(v));
    CHECK(bitsOf(floatStep(v, -0.0f)) == bitsOf(v));
    CHECK(bitsOf(floatStep(v, std::numeric_limits<float>::quiet_NaN())) == bitsOf(v));
}

}  // namespace

TEST_CASE("floatStep: the floats with a rule of their own") {
    using limits = std::numeric_limits<float>;
    for (float v : {0.0f, -0.0f, limits::denorm_min(), -limits::denorm_min(), limits::min(), -limits::min(),
                    limits::max(), -limits::max(), limits::infinity(), -limits::infinity(), limits::quiet_NaN(),
                    -limits::quiet_NaN(), 1.0f, -1.0f})
        checkStep(v);
}

TEST_CASE("floatStep: random bit patterns, every exponent and both signs") {
    Pcg32 rng(7, 11);
    for (int i = 0; i < 100000; ++i) checkStep(std::bit_cast<float>(rng.next()));
}

TEST_CASE("floatStep: the step is one float, towards the direction's sign") {
    CHECK(floatStep(1.0f, 3.0f) == std::nextafter(1.0f, 2.0f));
    CHECK(floatStep(1.0f, -1e-30f) == std::nextafter(1.0f, 0.0f));
    CHECK(floatStep(-2.0f, 1e-30f) == std::nextafter(-2.0f, 0.0f));
    CHECK(floatStep(0.0f, 1.0f) == std::numeric_limits<float>::denorm_min());
    CHECK(floatStep(0.0f, -1.0f) == -std::numeric_limits<float>::denorm_min());
}
