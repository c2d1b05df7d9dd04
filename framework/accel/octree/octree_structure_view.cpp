// The octree's StructureView from its nodes and their boxes, apart from the accelerator: the
// boxes come in (the accelerator's from the student's childBox, the grader's from its own), so
// this calls no assignment code and rtlab-grader, which links none, can draw what a worker sent.
#include "framework/accel/octree/octree_accelerator.h"

namespace rtlab {

StructureView octreeStructureView(const Octree& octree, std::span<const Bounds3f> nodeBoxes) {
    StructureView view;
    view.primIndices = octree.primIndices;
    view.nodes.resize(octree.nodes.size());
    for (uint32_t i = 0; i < octree.nodes.size(); ++i) {
        const OctreeNode& node = octree.nodes[i];
        StructureNode& out = view.nodes[i];
        if (i < nodeBoxes.size()) out.bounds = nodeBoxes[i];
        if (node.isLeaf()) {
            out.firstPrim = node.primStart;
            out.primCount = node.primCount;
            continue;
        }
        out.firstChild = static_cast<uint32_t>(view.children.size());
        out.childCount = kOctreeChildren;
        for (int k = 0; k < kOctreeChildren; ++k) view.children.push_back(node.firstChild + k);
    }
    return view;
}

}  // namespace rtlab
