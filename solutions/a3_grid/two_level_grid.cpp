// Reference solution beyond the lecture: a two-level grid, the answer to the teapot in a
// stadium (docs/a3-grid.md). The same three steps as the uniform grid, used twice: the top
// grid by the lecture's rule, then a grid of its own in every crowded top cell.
#include "framework/interface/a3_grid.h"

#include <algorithm>

namespace rtlab {

namespace {

std::span<const uint32_t> primitivesOf(const UniformGrid& grid, size_t cell) {
    return {grid.primIndices.data() + grid.cellStart[cell], grid.cellStart[cell + 1] - grid.cellStart[cell]};
}

Bounds3f cellBox(const UniformGrid& grid, const GridCell& c) {
    Vec3 lower = grid.bounds.lower + Vec3(float(c[0]), float(c[1]), float(c[2])) * grid.cellWidth;
    return Bounds3f(lower, lower + grid.cellWidth);
}

Bounds3f overlap(const Bounds3f& a, const Bounds3f& b) {
    Bounds3f o;
    o.lower = glm::max(a.lower, b.lower);
    o.upper = glm::min(a.upper, b.upper);
    return o;
}

// Where the walk through one grid over [tEnter, tExit] stands after a cell: whether a final hit
// was found. `visit` tests one cell's primitives.
template <typename Visit>
bool walk(const UniformGrid& grid, Traversal& traversal, float tEnter, float tExit, Hit* hit, Visit&& visit) {
    DdaState state = ddaSetup(grid, traversal.ray(), tEnter, tExit);
    do {
        traversal.countCellStep();
        if (visit(grid.cellIndex(state.cell), state)) return true;
        if (hit) {
            float cellExit = std::min({state.tNext[0], state.tNext[1], state.tNext[2]});
            if (hit->t <= cellExit) return true;
            state.tExit = std::min(state.tExit, hit->t);
        }
    } while (ddaStep(state, grid.resolution));
    return false;
}

// The closest-hit or any-hit query through both levels; for any-hit, hit is null and a cell's
// visit returns true at the first blocker.
bool query(const TwoLevelGrid& grid, Traversal& traversal, Hit* hit) {
    float tMax = hit ? hit->t : traversal.ray().tMax, tEnter;
    if (grid.top.primIndices.empty() || !traversal.hitsBox(grid.top.bounds, tMax, &tEnter)) return false;
    auto testAll = [&](std::span<const uint32_t> prims) {
        for (uint32_t prim : prims) {
            if (hit) traversal.intersectOnce(prim, *hit);
            else if (traversal.occludesOnce(prim)) return true;
        }
        return false;
    };
    return walk(grid.top, traversal, tEnter, tMax, hit, [&](size_t cell, const DdaState& state) {
        uint32_t child = grid.childOf[cell];
        if (child == TwoLevelGrid::kNoChild) return testAll(primitivesOf(grid.top, cell));
        // The child's part of the ray: inside its box and before the top cell's exit.
        const UniformGrid& sub = grid.children[child];
        float cellExit = std::min({state.tNext[0], state.tNext[1], state.tNext[2], state.tExit});
        float subEnter;
        if (!traversal.hitsBox(sub.bounds, std::min(cellExit, hit ? hit->t : cellExit), &subEnter)) return false;
        return walk(sub, traversal, subEnter, std::min(cellExit, hit ? hit->t : cellExit), hit,
                    [&](size_t subCell, const DdaState&) { return testAll(primitivesOf(sub, subCell)); });
    });
}

}  // namespace

TwoLevelGrid buildTwoLevelGrid(std::span<const Bounds3f> primBounds, const GridOptions& top, const GridOptions& child,
                               uint32_t refineAbove) {
    TwoLevelGrid grid;
    grid.top = gridFrame(primBounds, top);
    fillGridCells(grid.top, primBounds);
    grid.childOf.assign(grid.top.cellCount(), TwoLevelGrid::kNoChild);
    for (int z = 0; z < grid.top.resolution[2]; ++z)
        for (int y = 0; y < grid.top.resolution[1]; ++y)
            for (int x = 0; x < grid.top.resolution[0]; ++x) {
                size_t cell = grid.top.cellIndex({x, y, z});
                std::span<const uint32_t> prims = primitivesOf(grid.top, cell);
                if (prims.size() <= refineAbove) continue;
                // The child covers the part of the cell its primitives reach, by their count.
                std::vector<Bounds3f> boxes;
                Bounds3f reach;
                for (uint32_t prim : prims) {
                    boxes.push_back(primBounds[prim]);
                    reach.extend(primBounds[prim]);
                }
                UniformGrid sub = gridFrameOver(overlap(cellBox(grid.top, {x, y, z}), reach), prims.size(), child);
                fillGridCells(sub, boxes);
                for (uint32_t& local : sub.primIndices) local = prims[local];  // back to scene ids
                grid.childOf[cell] = static_cast<uint32_t>(grid.children.size());
                grid.children.push_back(std::move(sub));
            }
    return grid;
}

bool intersectTwoLevelGrid(const TwoLevelGrid& grid, Traversal& traversal, Hit& hit) {
    query(grid, traversal, &hit);
    return hit.found();
}

bool occludedTwoLevelGrid(const TwoLevelGrid& grid, Traversal& traversal) { return query(grid, traversal, nullptr); }

}  // namespace rtlab
