#include "viewer/structure_selection.h"

#include <algorithm>
#include <limits>

namespace rtlab::viewer {

NodeSelection selectNodes(const StructureView& view, DrawingStyle style, size_t budget, const std::vector<uint32_t>& wanted) {
    NodeSelection s;
    const size_t n = view.nodes.size();
    s.shippedOf.assign(n, kNoNode);
    if (n == 0) return s;
    // Breadth first from the root: parents and depths of every reachable node, so the budget
    // goes to whole levels from the top.
    std::vector<uint32_t> parentOf(n, kNoNode), order = {0};
    std::vector<uint16_t> depthOf(n, 0);
    std::vector<bool> seen(n, false);
    seen[0] = true;
    for (size_t i = 0; i < order.size(); ++i) {
        const StructureNode& node = view.nodes[order[i]];
        uint64_t end = uint64_t(node.firstChild) + node.childCount;
        if (node.childCount > 0 && end > view.children.size()) {
            ++s.malformed;
            continue;
        }
        for (uint64_t c = node.firstChild; c < end && node.childCount > 0; ++c) {
            uint32_t child = view.children[c];
            if (child >= n || seen[child]) {
                ++s.malformed;
                continue;
            }
            seen[child] = true;
            parentOf[child] = order[i];
            depthOf[child] = static_cast<uint16_t>(std::min<int>(depthOf[order[i]] + 1, std::numeric_limits<uint16_t>::max()));
            order.push_back(child);
        }
    }
    s.reachable = order.size();
    for (uint32_t v : order) s.maxDepth = std::max<uint32_t>(s.maxDepth, depthOf[v]);

    std::vector<bool> take(n, false);
    auto takeWithAncestors = [&](uint32_t v) {
        while (v != kNoNode && !take[v]) {
            take[v] = true;
            v = parentOf[v];
        }
    };
    if (style == DrawingStyle::Cells) {
        // The occupied cells, in order, up to the budget; the levels above them come along.
        size_t cells = 0;
        for (uint32_t v : order) {
            const StructureNode& node = view.nodes[v];
            if (node.childCount == 0 && node.primCount > 0 && cells < budget) {
                takeWithAncestors(v);
                ++cells;
            }
        }
        take[0] = true;
        s.completeDepth = cells < budget ? s.maxDepth : 0;
    } else {
        // Whole levels while they fit.
        size_t i = 0;
        while (i < order.size()) {
            size_t j = i;
            while (j < order.size() && depthOf[order[j]] == depthOf[order[i]]) ++j;
            if (j > budget && i > 0) break;
            for (size_t k = i; k < j; ++k) take[order[k]] = true;
            s.completeDepth = depthOf[order[i]];
            i = j;
        }
    }
    for (uint32_t v : wanted)
        if (v < n && seen[v]) takeWithAncestors(v);
    for (uint32_t v : order)
        if (take[v]) {
            s.shippedOf[v] = static_cast<uint32_t>(s.nodes.size());
            s.nodes.push_back(v);
            s.parent.push_back(parentOf[v] == kNoNode ? kNoNode : s.shippedOf[parentOf[v]]);
            s.depth.push_back(depthOf[v]);
        }
    return s;
}

}  // namespace rtlab::viewer
