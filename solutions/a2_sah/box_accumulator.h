// A box grown one primitive box at a time, as a bucket of the bucketed SAH is: Bounds3f::extend
// with the same result bit for bit, in fewer instructions where SSE2 is available.
//
// Why: binning extends one bucket box per primitive per level of the tree, the hottest statement
// of the whole build. Compiled for baseline x86-64 (no AVX), Bounds3f::extend costs three or
// four instructions per coordinate; four-wide min/max does each corner in one. Elsewhere the
// plain Bounds3f is used.
#pragma once

#include "framework/core/bounds.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rtlab {

#if defined(__SSE2__)

class BoxAccumulator {
public:
    void extend(const Bounds3f& b) {
        // The 16 bytes at lower are lower.xyz and upper.x; those at lower.z are lower.z and
        // upper.xyz, rotated so upper.xyz land in lanes 0-2. Lane 3 is never read back.
        // _mm_min_ps(b, acc) is (b < acc) ? b : acc, exactly glm::min(acc, b) as extend computes
        // it (a NaN coordinate is skipped the same way), and likewise for max.
        __m128 lower = _mm_loadu_ps(&b.lower.x);
        __m128 upperAt = _mm_loadu_ps(&b.lower.z);
        __m128 upper = _mm_shuffle_ps(upperAt, upperAt, _MM_SHUFFLE(0, 3, 2, 1));
        lower_ = _mm_min_ps(lower, lower_);
        upper_ = _mm_max_ps(upper, upper_);
    }

    Bounds3f box() const {
        alignas(16) float lower[4], upper[4];
        _mm_store_ps(lower, lower_);
        _mm_store_ps(upper, upper_);
        Bounds3f b;
        b.lower = Vec3(lower[0], lower[1], lower[2]);
        b.upper = Vec3(upper[0], upper[1], upper[2]);
        return b;
    }

private:
    __m128 lower_ = _mm_set1_ps(kInfinity);
    __m128 upper_ = _mm_set1_ps(-kInfinity);
};

#else

class BoxAccumulator {
public:
    void extend(const Bounds3f& b) { box_.extend(b); }
    Bounds3f box() const { return box_; }

private:
    Bounds3f box_;
};

#endif

}  // namespace rtlab
