// Arbitrary output variables: teaching images written next to the rendered one
// (docs/rendering.md, "AOVs").
//   normal  the viewer-facing shading normal n as 0.5 n + 0.5 (RGB); misses black
//   depth   the hit distance t along the unit-length camera ray (one channel); misses +inf
//           in float files, and in integer files t / (largest t) with misses 0
//   prim    a stable hash colour of the primitive id (RGB); misses black
//   cost    node visits + primitive tests of the primary ray through a colour ramp, scaled
//           by the image's maximum cost (RGB); the maximum is reported by the caller
#pragma once

#include "framework/render/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

enum class Aov { Normal, Depth, Primitive, Cost };

// Parses "normal" | "depth" | "prim" | "cost"; throws rtlab::Error naming the valid ones.
Aov parseAov(const std::string& name);
const char* aovName(Aov aov);

// Per-pixel raw data the renderer keeps for the AOVs it was asked for.
struct AovBuffers {
    Image normal;                   // RGB, 0.5 n + 0.5
    Image depth;                    // 1 channel, t or +inf
    std::vector<uint32_t> primitive;  // id or kNoHit
    std::vector<uint32_t> cost;       // node visits + primitive tests of the primary ray
};

// The image to write for one AOV. integerFile selects the mapping for 8/16-bit files.
Image aovImage(Aov aov, const AovBuffers& buffers, int width, int height, bool integerFile);

// The colour of primitive id prim: a hash, so neighbouring ids get unrelated colours.
Vec3 primitiveColour(uint32_t prim);

// A black-purple-orange-yellow ramp (close to matplotlib's inferno) for x in [0, 1].
Vec3 heatColour(float x);

uint32_t maxCost(const AovBuffers& buffers);

}  // namespace rtlab
