// A closed test mesh, for the grader's scenes and the framework's tests: an icosahedron
// subdivided `levels` times, its vertices on the unit sphere, indexed so that neighbouring
// triangles share bit-identical vertices (docs/conventions.md#stress-catalogue, TRI-04). Two
// levels give 162 vertices and 320 triangles. Header-only: the a0 stress test built with FMA
// links nothing of the framework.
#pragma once

#include "framework/core/vec.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace rtlab {

struct IndexedMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
};

inline IndexedMesh icosphereMesh(int levels) {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    IndexedMesh mesh;
    mesh.positions = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    auto& v = mesh.positions;
    for (Vec3& p : v) p = glm::normalize(p);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto [it, inserted] = midpoints.try_emplace(std::minmax(a, b), static_cast<uint32_t>(v.size()));
            if (inserted) v.push_back(glm::normalize(v[a] + v[b]));
            return it->second;
        };
        std::vector<std::array<uint32_t, 3>> finer;
        for (auto [a, b, c] : mesh.triangles) {
            uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        mesh.triangles = std::move(finer);
    }
    return mesh;
}

}  // namespace rtlab
