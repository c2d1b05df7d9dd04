// What the viewer (viewer/, docs/viewer.md) needs to draw a structure, beyond its StructureView:
// how to show it and, for trees cut by planes, each plane as a polygon. Every structure's
// registry entry names its drawing function (AcceleratorType::draw, accelerator_registry.h),
// written beside it; a structure without one is drawn by drawLevels. Numbers only, computed
// from the StructureView alone, so the grader can draw what a worker returned as well as the
// framework can draw what it built.
#pragma once

#include "framework/accel/structure_view.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

enum class DrawingStyle : uint8_t {
    Levels = 0,  // a tree of boxes: a depth slider shows one level, leaves and their primitives
    Cells = 1,   // a grid: the occupied cells, coloured by how many primitives they hold
    Planes = 2,  // a tree of planes: the split planes by depth, and the leaves' cells
};

// A node's plane cut to the node's own cell: a convex polygon, its corners in order.
struct DrawnPlane {
    uint32_t node = 0;
    std::vector<Vec3> polygon;
};

struct StructureDrawing {
    DrawingStyle style = DrawingStyle::Levels;
    // False when the nodes' boxes say nothing (a BSP node's cell is a polytope, its box the tree's).
    bool boxesMeaningful = true;
    std::string valueName;           // what values hold, shown on hover ("SAH share"); empty: nothing
    std::vector<float> values;       // one per node, or empty
    std::vector<DrawnPlane> planes;  // Planes: one per interior node with a plane
};

// drawn: per node, whether the page shows it (a deep tree's page shows its top levels and the
// nodes near a ray, viewer/structure_selection.h), so that per-node work is done for those
// alone; every drawn node's ancestors are drawn too. Empty: every node.
using NodeMask = std::vector<bool>;
using StructureDrawer = StructureDrawing (*)(const StructureView& view, const NodeMask& drawn);

StructureDrawing drawLevels(const StructureView& view, const NodeMask& drawn);
StructureDrawing drawCells(const StructureView& view, const NodeMask& drawn);
// Each drawn interior node's plane (view.planes) clipped to the node's box and to the sides of
// its ancestors' planes it lies on: a KD-tree's rectangles and a BSP's convex polygons alike.
StructureDrawing drawPlanes(const StructureView& view, const NodeMask& drawn);

// Each node's share of the tree's SAH cost (sahCost, structure_view.h), for a BVH's hover text.
std::vector<float> sahShares(const StructureView& view);

// The drawing of the structure an --accel name builds (its registry entry's draw, or drawLevels).
// Throws rtlab::Error for a name the registry does not know.
StructureDrawing drawStructure(const std::string& acceleratorName, const StructureView& view, const NodeMask& drawn = {});
// The drawing drawStructure uses for that name. Both are in registered_drawing.cpp, which links
// the registry and with it every accelerator: rtlab-grader, which links no assignment code,
// names a drawing function itself (drawBvh, drawCells, ...) instead.
StructureDrawer structureDrawer(const std::string& acceleratorName);

}  // namespace rtlab
