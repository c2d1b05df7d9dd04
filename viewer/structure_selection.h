// Which nodes of a structure a page carries (docs/viewer.md#scale): a deep tree or a fine grid
// would freeze a browser, so a page gets the top levels up to a budget, every node a ray's
// trace visits, and their ancestors. The view may come from a student's worker: every index is
// checked, a node reached twice or out of range is left out, and the count of what was left
// out is kept for a note on the page.
#pragma once

#include "framework/accel/structure_drawing.h"
#include "framework/accel/structure_view.h"

#include <cstdint>
#include <vector>

namespace rtlab::viewer {

inline constexpr uint32_t kNoNode = 0xffffffffu;

struct NodeSelection {
    std::vector<uint32_t> nodes;   // indices into view.nodes, parents before children
    std::vector<uint32_t> parent;  // per selected node: the parent's position in `nodes`, or kNoNode
    std::vector<uint16_t> depth;   // per selected node
    std::vector<uint32_t> shippedOf;  // per view node: its position in `nodes`, or kNoNode
    uint32_t completeDepth = 0;    // every node down to this depth is carried
    uint32_t maxDepth = 0;         // of the whole structure
    size_t reachable = 0;          // nodes reachable from the root
    size_t malformed = 0;          // child links out of range or to a node seen before
};

// budget: nodes for a tree; for DrawingStyle::Cells, occupied leaves. `wanted` nodes (those a
// trace visits) are always carried with their ancestors, beyond the budget.
NodeSelection selectNodes(const StructureView& view, DrawingStyle style, size_t budget, const std::vector<uint32_t>& wanted);

}  // namespace rtlab::viewer
