// The interface every acceleration structure implements (brute force, the BVH family, the
// grid, later the trees): build once over a primitive set, then answer closest-hit and any-hit
// queries. Work is counted through the Traversal context (framework/interface/traversal.h).
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/accel/structure_view.h"
#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/traversal_stats.h"

#include <memory>
#include <string>

namespace rtlab {

class Accelerator {
public:
    virtual ~Accelerator() = default;

    virtual void build(const PrimitiveSet& primitives) = 0;
    // Closest hit in (ray.tMin, ray.tMax]; hit.prim == kNoHit on a miss.
    virtual Hit intersect(const Ray& ray, TraversalStats& stats) const = 0;
    // Any hit in (ray.tMin, ray.tMax]: for shadow rays.
    virtual bool occluded(const Ray& ray, TraversalStats& stats) const = 0;
    virtual StructureView structure() const = 0;
    // Bytes the structure keeps beyond the primitive set (nodes, index lists, copies).
    virtual size_t memoryBytes() const = 0;
};

// What --accel and its companion flags ask for. The name is parsed by the accelerator
// registry (accelerator_registry.h); the flags override the BVH options of the same meaning
// (leaf, traversal, axes) and are an error for a structure that has no such option.
struct AcceleratorSpec {
    std::string name = "bvh-buckets";
    int maxLeaf = 4;
    bool recursiveTraversal = false;  // the lecture's recursive BVH traversal instead of ordered
    bool sahAllAxes = false;          // bvh-sah, bvh-buckets: try x, y and z, not only the longest axis
};

// Throws rtlab::Error naming the problem and the valid names when spec cannot be built.
std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec);

// The structures and options this executable knows, one line each, for help texts.
std::string acceleratorNames();

}  // namespace rtlab
