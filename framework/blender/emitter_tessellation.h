// Cutting an emissive triangle into smaller ones for Blender. Cycles 3.4 samples a mesh light's
// triangle by solid angle when its longest edge is longer than the shading point's distance
// to the triangle's plane, and that path is biased low (a 1 m square of two triangles 1 m above
// a plane: 4 % low far from it; docs/verification.md#6-blender-cycles-references); with short
// edges it samples by area, without bias.
#pragma once

#include "framework/core/vec.h"

#include <array>
#include <vector>

namespace rtlab {

struct TriangleCut {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;                     // when the triangle had vertex normals
    std::vector<std::array<uint32_t, 3>> indices;  // into positions, same winding as the input
};

// At most this many parts per edge (65536 triangles for one): an emitter larger than
// 256 x maxEdge keeps longer edges rather than filling the memory.
inline constexpr int kMaxCutsPerEdge = 256;

// The number of parts each edge is cut into so that no edge is longer than maxEdge:
// ceil(longest edge / maxEdge), at least 1, at most kMaxCutsPerEdge.
int cutsPerEdge(const std::array<Vec3, 3>& vertices, double maxEdge);

// Cuts the triangle p0 p1 p2 into k^2 triangles similar to it (k parts per edge): the points
// p0 + (i/k)(p1 - p0) + (j/k)(p2 - p0), i + j <= k, computed in double (the corners exactly);
// each part keeps the winding of p0 p1 p2, so it emits from the same side. Normals (optional: empty or three) are
// interpolated the same way and normalised.
TriangleCut cutTriangle(const std::array<Vec3, 3>& vertices, const std::vector<Vec3>& normals, int k);

}  // namespace rtlab
