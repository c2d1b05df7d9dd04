#include "framework/accel/grid/grid_accelerator.h"

#include "framework/accel/accelerator_registry.h"
#include "framework/accel/grid/grid_adapter.h"
#include "framework/accel/grid/grid_structure_view.h"

namespace rtlab {

void GridAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    grid_ = GridAdapter::build(primitives, options_, insertion_);
}

Hit GridAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    Hit hit;
    hit.t = ray.tMax;
    Traversal traversal(*primitives_, ray, stats);
    GridAdapter::intersect(grid_, traversal, hit);
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool GridAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    return GridAdapter::occluded(grid_, traversal);
}

std::unique_ptr<Accelerator> GridAccelerator::create(const AcceleratorParameters& p) {
    GridOptions options;
    options.cellsPerPrimitive = p.number("C");
    options.maxResolution = p.integer("res");
    return std::make_unique<GridAccelerator>(options, p.word("insert") == "exact" ? GridInsertion::Exact : GridInsertion::Box);
}

StructureView GridAccelerator::structure() const {
    return gridStructureView(grid_, grid_.cellStart, grid_.primIndices);
}

AcceleratorType gridType() {
    AcceleratorType type{"grid",
            "uniform grid with the 3D-DDA (a3)",
            {{"C", "cells per primitive: the lecture's rule cells ~= C * N", "27", 1, 1000, false, {}},
             {"res", "most cells along any axis", "64", 1, 1024, true, {}},
             {"insert", "a triangle into every cell of its box, or only those its surface overlaps (a4's test)", "box", 0, 0, false,
              {"box", "exact"}}},
            GridAccelerator::create,
            {"grid:C=1", "grid:C=3", "grid:C=9", "grid:C=27", "grid:C=81", "grid:insert=exact"}};
    type.draw = drawCells;  // the occupied cells, by how many primitives they hold
    return type;
}

}  // namespace rtlab
