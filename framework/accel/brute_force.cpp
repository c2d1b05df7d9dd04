#include "framework/accel/brute_force.h"

#include "framework/accel/accelerator_registry.h"
#include "framework/interface/traversal.h"

namespace rtlab {

Hit BruteForce::intersect(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    Hit hit;
    hit.t = ray.tMax;
    for (uint32_t prim = 0; prim < primitives_->size(); ++prim) traversal.intersect(prim, hit);
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool BruteForce::occluded(const Ray& ray, TraversalStats& stats) const {
    Traversal traversal(*primitives_, ray, stats);
    for (uint32_t prim = 0; prim < primitives_->size(); ++prim)
        if (traversal.occludes(prim)) return true;
    return false;
}

StructureView BruteForce::structure() const {
    StructureView view;
    StructureNode leaf;
    for (uint32_t prim = 0; prim < primitives_->size(); ++prim) {
        leaf.bounds.extend(primitives_->bounds(prim));
        view.primIndices.push_back(prim);
    }
    leaf.primCount = primitives_->size();
    view.nodes.push_back(leaf);
    return view;
}

}  // namespace rtlab

namespace rtlab {

AcceleratorType bruteForceType() {
    return {"brute", "every primitive for every ray: the baseline", {},
            [](const AcceleratorParameters&) { return std::make_unique<BruteForce>(); }, {"brute"}};
}

}  // namespace rtlab
