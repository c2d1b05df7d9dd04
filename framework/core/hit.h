// The result of a closest-hit query: which primitive, where along the ray, and the
// barycentric coordinates the shading step needs. prim == kNoHit means a miss.
#pragma once

#include "framework/core/vec.h"

#include <cstdint>

namespace rtlab {

inline constexpr uint32_t kNoHit = 0xffffffffu;

struct Hit {
    float t = kInfinity;
    uint32_t prim = kNoHit;
    float b1 = 0.0f;  // barycentric weight of a triangle's second vertex
    float b2 = 0.0f;  // ... and of its third; the first has 1 - b1 - b2

    bool found() const { return prim != kNoHit; }
};

}  // namespace rtlab
