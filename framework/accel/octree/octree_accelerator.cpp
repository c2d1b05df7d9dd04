#include "framework/accel/octree/octree_accelerator.h"

#include "framework/accel/accelerator_registry.h"
#include "framework/accel/octree/octree_adapter.h"
#include "framework/interface/a4_octree.h"

namespace rtlab {

void OctreeAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    octree_ = OctreeAdapter::build(primitives, options_);
}

Hit OctreeAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    Hit hit;
    hit.t = ray.tMax;
    Traversal traversal(*primitives_, ray, stats);
    OctreeAdapter::intersect(octree_, traversal, hit);
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool OctreeAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    return OctreeAdapter::occluded(octree_, traversal);
}

StructureView OctreeAccelerator::structure() const { return octreeStructureView(octree_); }

StructureView octreeStructureView(const Octree& octree) {
    StructureView view;
    view.primIndices = octree.primIndices;
    view.nodes.resize(octree.nodes.size());
    if (octree.nodes.empty()) return view;
    view.nodes[0].bounds = octree.root;
    // Parents come before their children in the array, so one pass hands every box down.
    for (uint32_t i = 0; i < octree.nodes.size(); ++i) {
        const OctreeNode& node = octree.nodes[i];
        StructureNode& out = view.nodes[i];
        if (node.isLeaf()) {
            out.firstPrim = node.primStart;
            out.primCount = node.primCount;
            continue;
        }
        out.firstChild = static_cast<uint32_t>(view.children.size());
        out.childCount = kOctreeChildren;
        for (int k = 0; k < kOctreeChildren; ++k) {
            view.children.push_back(node.firstChild + k);
            view.nodes[node.firstChild + k].bounds = childBox(out.bounds, k);
        }
    }
    return view;
}

AcceleratorType octreeType() {
    AcceleratorType type{"octree",
            "octree with Revelles' parametric walk (a4)",
            {{"maxPrims", "a node with more primitives is split", "8", 1, 65535, true, {}},
             {"maxDepth", "deepest level (the root is 0)", "10", 0, 20, true, {}},
             {"insert", "triangles into the children their surface overlaps, or their box", "exact", 0, 0, false, {"exact", "box"}}},
            [](const AcceleratorParameters& p) {
                OctreeOptions options;
                options.maxPrims = static_cast<uint32_t>(p.integer("maxPrims"));
                options.maxDepth = p.integer("maxDepth");
                options.insertion = p.word("insert") == "box" ? OctreeInsertion::Box : OctreeInsertion::Exact;
                return std::make_unique<OctreeAccelerator>(options);
            },
            {"octree", "octree:insert=box", "octree:maxDepth=16"}};
    type.draw = drawLevels;  // nodes by depth
    return type;
}

}  // namespace rtlab
