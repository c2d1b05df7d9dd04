#include "framework/blender/emitter_tessellation.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

int cutsPerEdge(const std::array<Vec3, 3>& v, double maxEdge) {
    double longest = 0.0;
    for (int e = 0; e < 3; ++e) longest = std::max(longest, glm::length(DVec3(v[(e + 1) % 3]) - DVec3(v[e])));
    double parts = std::ceil(longest / maxEdge);
    if (!(parts >= 1.0)) return 1;  // NaN: the export refuses the non-finite vertex later
    return static_cast<int>(std::min(parts, double(kMaxCutsPerEdge)));
}

TriangleCut cutTriangle(const std::array<Vec3, 3>& v, const std::vector<Vec3>& normals, int k) {
    TriangleCut cut;
    // Row j of the lattice holds the points i = 0 .. k - j; first(j) is its first index.
    auto first = [k](int j) { return static_cast<uint32_t>(j * (k + 1) - j * (j - 1) / 2); };
    // From the first corner along the two edges: the corners come out exactly.
    auto at = [k](const auto& a, const auto& b, const auto& c, int i, int j) {
        double u = double(i) / k, w = double(j) / k;
        return DVec3(a) + u * (DVec3(b) - DVec3(a)) + w * (DVec3(c) - DVec3(a));
    };
    for (int j = 0; j <= k; ++j)
        for (int i = 0; i + j <= k; ++i) {
            cut.positions.push_back(Vec3(at(v[0], v[1], v[2], i, j)));
            if (!normals.empty()) cut.normals.push_back(Vec3(glm::normalize(at(normals[0], normals[1], normals[2], i, j))));
        }
    for (int j = 0; j < k; ++j)
        for (int i = 0; i + j < k; ++i) {
            uint32_t a = first(j) + i, b = a + 1, c = first(j + 1) + i;
            cut.indices.push_back({a, b, c});                               // (i,j) (i+1,j) (i,j+1)
            if (i + j + 1 < k) cut.indices.push_back({b, c + 1, c});        // (i+1,j) (i+1,j+1) (i,j+1)
        }
    return cut;
}

}  // namespace rtlab
