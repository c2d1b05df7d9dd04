// Arbitrary output variables: teaching images written next to the rendered one
// (docs/rendering.md, "AOVs").
//   normal  the viewer-facing shading normal n as 0.5 n + 0.5 (RGB); misses black
//   depth   the hit distance t along the unit-length camera ray (one channel); misses +inf
//           in float files, and in integer files t / (largest t) with misses 0
//   prim    a stable hash colour of the primitive id (RGB); misses black
//   cost    all the work of the primary ray (box tests, cell and plane steps, primitive
//           tests) through a colour ramp, scaled by the image's maximum (RGB); the maximum is
//           reported by the caller
//   steps   the structure's own work alone (box tests, cell and plane steps: the cells a
//           grid's ray visits), the same way
#pragma once

#include "framework/render/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

enum class Aov { Normal, Depth, Primitive, Cost, Steps };

// Parses "normal" | "depth" | "prim" | "cost" | "steps"; throws rtlab::Error naming the valid ones.
Aov parseAov(const std::string& name);
const char* aovName(Aov aov);

// Per-pixel raw data the renderer keeps for the AOVs it was asked for.
struct AovBuffers {
    Image normal;                   // RGB, 0.5 n + 0.5
    Image depth;                    // 1 channel, t or +inf
    std::vector<uint32_t> primitive;  // id or kNoHit
    std::vector<uint32_t> cost;       // TraversalStats::steps() + primitive tests of the primary ray
    std::vector<uint32_t> steps;      // TraversalStats::steps() of the primary ray
};

// The image to write for one AOV. integerFile selects the mapping for 8/16-bit files.
Image aovImage(Aov aov, const AovBuffers& buffers, int width, int height, bool integerFile);

// The colour of primitive id prim: a hash, so neighbouring ids get unrelated colours.
Vec3 primitiveColour(uint32_t prim);

// A black-purple-orange-yellow ramp (close to matplotlib's inferno) for x in [0, 1].
Vec3 heatColour(float x);

// The largest count of a cost or steps buffer (0 when empty): the top of its colour ramp.
uint32_t maxCount(const std::vector<uint32_t>& counts);

}  // namespace rtlab
