#include "framework/accel/grid/grid_structure_view.h"

#include "framework/interface/a3_grid.h"

namespace rtlab {

StructureView gridStructureView(const UniformGrid& frame, std::span<const uint32_t> cellStart,
                                std::span<const uint32_t> primIndices) {
    StructureView view;
    view.primIndices.assign(primIndices.begin(), primIndices.end());
    StructureNode root;
    root.bounds = frame.bounds;
    root.firstChild = 0;
    root.childCount = static_cast<uint32_t>(frame.cellCount());
    view.nodes.push_back(root);
    for (int z = 0; z < frame.resolution[2]; ++z)
        for (int y = 0; y < frame.resolution[1]; ++y)
            for (int x = 0; x < frame.resolution[0]; ++x) {
                size_t c = frame.cellIndex({x, y, z});
                StructureNode cell;
                cell.bounds = gridCellBox(frame, {x, y, z});
                cell.firstPrim = cellStart[c];
                cell.primCount = cellStart[c + 1] - cellStart[c];
                view.children.push_back(static_cast<uint32_t>(view.nodes.size()));
                view.nodes.push_back(cell);
            }
    return view;
}

}  // namespace rtlab
