#include "framework/accel/bsp/bsp_accelerator.h"

#include "framework/accel/accelerator_registry.h"
#include "framework/accel/bsp/bsp_adapter.h"

namespace rtlab {

void BspAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    tree_ = BspAdapter::build(primitives, options_);
}

Hit BspAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    Hit hit;
    hit.t = ray.tMax;
    Traversal traversal(*primitives_, ray, stats);
    BspAdapter::intersect(tree_, traversal, hit);
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool BspAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    return BspAdapter::occluded(tree_, traversal);
}

std::unique_ptr<Accelerator> BspAccelerator::create(const AcceleratorParameters& p) {
    BspOptions options;
    options.maxPrims = static_cast<uint32_t>(p.integer("leaf"));
    options.maxDepth = p.integer("depth");
    return std::make_unique<BspAccelerator>(options);
}

StructureView BspAccelerator::structure() const { return bspStructureView(tree_); }

StructureView bspStructureView(const BspTree& tree) {
    StructureView view;
    view.primIndices = tree.primIndices;
    for (uint32_t i = 0; i < tree.nodes.size(); ++i) {
        const BspNode& node = tree.nodes[i];
        StructureNode out{tree.bounds, 0, 0, node.firstPrim, node.primCount};
        StructurePlane plane;
        if (!node.leaf) {
            out.firstChild = static_cast<uint32_t>(view.children.size());
            out.childCount = 2;
            view.children.push_back(i + 1);  // back: the node right after it
            view.children.push_back(node.front);
            plane = StructurePlane{node.normal, node.offset};
        }
        view.nodes.push_back(out);
        view.planes.push_back(plane);
    }
    return view;
}

AcceleratorType bspType() {
    AcceleratorType type{"bsp",
            "BSP tree on the triangles' own planes, an autopartition (a5, optional)",
            {{"leaf", "a cell with at most this many primitives is a leaf", "2", 1, 65535, true, {}},
             {"depth", "depth limit", "40", 1, kBspMaxDepthLimit, true, {}}},
            BspAccelerator::create,
            {}};  // no bench rows: an autopartition is taught, not tuned
    type.draw = [](const StructureView& view, const NodeMask& drawn) {
        StructureDrawing drawing = drawPlanes(view, drawn);
        drawing.boxesMeaningful = false;  // every node carries the tree's box
        return drawing;
    };
    return type;
}

}  // namespace rtlab
