#include "framework/accel/grid/two_level_grid_accelerator.h"

#include "framework/accel/accelerator_registry.h"
#include "framework/interface/a3_grid.h"

namespace rtlab {

void TwoLevelGridAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    grid_ = buildTwoLevelGrid(primitives.allBounds(), top_, child_, refineAbove_);
}

Hit TwoLevelGridAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    Hit hit;
    hit.t = ray.tMax;
    Traversal traversal(*primitives_, ray, stats);
    intersectTwoLevelGrid(grid_, traversal, hit);
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool TwoLevelGridAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    return occludedTwoLevelGrid(grid_, traversal);
}

size_t TwoLevelGridAccelerator::memoryBytes() const {
    size_t words = grid_.top.cellStart.size() + grid_.top.primIndices.size() + grid_.childOf.size();
    for (const UniformGrid& child : grid_.children) words += child.cellStart.size() + child.primIndices.size();
    return words * sizeof(uint32_t) + grid_.children.size() * sizeof(UniformGrid);
}

std::unique_ptr<Accelerator> TwoLevelGridAccelerator::create(const AcceleratorParameters& p) {
    GridOptions top, child;
    top.cellsPerPrimitive = p.number("top");
    child.cellsPerPrimitive = p.number("C");
    top.maxResolution = child.maxResolution = p.integer("res");
    return std::make_unique<TwoLevelGridAccelerator>(top, child, static_cast<uint32_t>(p.integer("refine")));
}

StructureView TwoLevelGridAccelerator::structure() const {
    StructureView view;
    auto addGrid = [&view](const UniformGrid& grid, uint32_t parent) {
        StructureNode& node = view.nodes[parent];
        node.firstChild = static_cast<uint32_t>(view.children.size());
        node.childCount = static_cast<uint32_t>(grid.cellCount());
        std::vector<uint32_t> cells;
        for (int z = 0; z < grid.resolution[2]; ++z)
            for (int y = 0; y < grid.resolution[1]; ++y)
                for (int x = 0; x < grid.resolution[0]; ++x) {
                    size_t c = grid.cellIndex({x, y, z});
                    StructureNode cell;
                    cell.bounds = gridCellBox(grid, {x, y, z});
                    cell.firstPrim = static_cast<uint32_t>(view.primIndices.size());
                    cell.primCount = grid.cellStart[c + 1] - grid.cellStart[c];
                    view.primIndices.insert(view.primIndices.end(), grid.primIndices.begin() + grid.cellStart[c],
                                            grid.primIndices.begin() + grid.cellStart[c + 1]);
                    view.children.push_back(static_cast<uint32_t>(view.nodes.size()));
                    cells.push_back(static_cast<uint32_t>(view.nodes.size()));
                    view.nodes.push_back(cell);
                }
        return cells;
    };
    StructureNode root;
    root.bounds = grid_.top.bounds;
    view.nodes.push_back(root);
    std::vector<uint32_t> topCells = addGrid(grid_.top, 0);
    // A refined cell becomes an interior node whose children are its child grid's cells (its
    // own primitive list stays, as the top level stores it).
    for (size_t c = 0; c < topCells.size(); ++c)
        if (grid_.childOf[c] != TwoLevelGrid::kNoChild) addGrid(grid_.children[grid_.childOf[c]], topCells[c]);
    return view;
}

AcceleratorType twoLevelGridType() {
    AcceleratorType type{"grid2",
            "two-level grid: crowded cells refined by their own grid (a3, beyond the lecture)",
            // The top grid only has to find the crowded regions: a coarse one leaves fewer empty
            // cells to step through around them (docs/a3-grid.md#beyond-the-lecture-two-level-grids).
            {{"top", "cells per primitive of the top grid", "3", 1, 1000, false, {}},
             {"C", "cells per primitive of each child grid", "27", 1, 1000, false, {}},
             {"res", "most cells along any axis of either level", "64", 1, 1024, true, {}},
             {"refine", "a top cell with more primitives than this gets a child grid", "8", 1, 1000000, true, {}}},
            TwoLevelGridAccelerator::create,
            {"grid2"}};
    type.draw = drawCells;  // the occupied cells of both levels
    return type;
}

}  // namespace rtlab
