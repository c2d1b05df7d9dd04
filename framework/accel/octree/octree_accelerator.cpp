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

std::unique_ptr<Accelerator> OctreeAccelerator::create(const AcceleratorParameters& p) {
    OctreeOptions options;
    options.maxPrims = static_cast<uint32_t>(p.integer("maxPrims"));
    options.maxDepth = p.integer("maxDepth");
    options.insertion = p.word("insert") == "box" ? OctreeInsertion::Box : OctreeInsertion::Exact;
    return std::make_unique<OctreeAccelerator>(options);
}

StructureView OctreeAccelerator::structure() const { return octreeStructureView(octree_); }

StructureView octreeStructureView(const Octree& octree) {
    // Parents come before their children in the array, so one pass hands every box down.
    std::vector<Bounds3f> boxes(octree.nodes.size());
    if (!boxes.empty()) boxes[0] = octree.root;
    for (uint32_t i = 0; i < octree.nodes.size(); ++i)
        if (!octree.nodes[i].isLeaf())
            for (int k = 0; k < kOctreeChildren; ++k) boxes[octree.nodes[i].firstChild + k] = childBox(boxes[i], k);
    return octreeStructureView(octree, boxes);
}

AcceleratorType octreeType() {
    AcceleratorType type{"octree",
            "octree with Revelles' parametric walk (a4)",
            {{"maxPrims", "a node with more primitives is split", "8", 1, 65535, true, {}},
             {"maxDepth", "deepest level (the root is 0)", "10", 0, 20, true, {}},
             {"insert", "triangles into the children their surface overlaps, or their box", "exact", 0, 0, false, {"exact", "box"}}},
            OctreeAccelerator::create,
            {"octree", "octree:insert=box", "octree:maxDepth=16"}};
    type.draw = drawLevels;  // nodes by depth
    return type;
}

}  // namespace rtlab
