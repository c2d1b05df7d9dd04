#include "framework/accel/kdtree/kdtree_accelerator.h"

#include "framework/accel/accelerator_registry.h"

namespace rtlab {

void KdTreeAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    tree_ = KdTreeAdapter::build(primitives, options_, builder_);
}

Hit KdTreeAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    Hit hit;
    hit.t = ray.tMax;
    Traversal traversal(*primitives_, ray, stats);
    KdTreeAdapter::intersect(tree_, traversal, hit);
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool KdTreeAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    return KdTreeAdapter::occluded(tree_, traversal);
}

std::unique_ptr<Accelerator> KdTreeAccelerator::create(const AcceleratorParameters& p) {
    KdTreeOptions options;
    options.costs = KdCosts{p.number("KT"), p.number("KI"), p.number("eb")};
    options.maxPrims = static_cast<uint32_t>(p.integer("leaf"));
    options.maxDepth = p.integer("depth");
    return std::make_unique<KdTreeAccelerator>(options, p.word("build") == "sort" ? KdBuilder::Sort : KdBuilder::NlogN);
}

StructureView KdTreeAccelerator::structure() const { return kdTreeStructureView(tree_); }

AcceleratorType kdTreeType() {
    AcceleratorType type{"kdtree",
            "KD-tree built by the SAH, traversed front to back (a5)",
            {{"build", "builder: nlogn (Wald-Havran, events sorted once) or sort (every node sorts its own)", "nlogn", 0, 0, false,
              {"nlogn", "sort"}},
             {"KT", "SAH cost of a plane step (K_T)", "1", 0, 1000, false, {}},
             {"KI", "SAH cost of a primitive test (K_I)", "80", 0.001, 1000, false, {}},
             {"eb", "empty-space bonus: the share of a split's cost forgiven when a side is empty", "0.5", 0, 1, false, {}},
             {"leaf", "a node with at most this many primitives is a leaf (maxPrims)", "1", 1, 65535, true, {}},
             {"depth", "depth limit; 0: round(8 + 1.3 floor(log2 N))", "0", 0, kKdMaxDepthLimit, true, {}}},
            KdTreeAccelerator::create,
            {"kdtree", "kdtree:build=sort"}};
    type.draw = drawPlanes;  // the split planes by depth, and the leaves
    return type;
}

}  // namespace rtlab
