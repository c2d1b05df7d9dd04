// The interface every acceleration structure implements (brute force, the BVH family, later
// grids and trees): build once over a primitive set, then answer closest-hit and any-hit
// queries. Work is counted through the Traversal context (traversal.h).
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/accel/structure_view.h"
#include "framework/accel/traversal_stats.h"
#include "framework/core/hit.h"
#include "framework/core/ray.h"

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

// Accelerator names accepted by --accel (docs/conventions.md):
//   brute | bvh-median | bvh-middle | bvh-equal | bvh-sah | bvh-buckets[:B]
// and, where an executable links them, other traversals of the same trees (bvh_layouts.h):
//   bvh4-median ... bvh4-buckets[:B], bvh8-... likewise (the wide BVHs of fast/)
struct AcceleratorSpec {
    std::string name = "bvh-buckets";
    int maxLeaf = 4;
    bool recursiveTraversal = false;  // the lecture's recursive BVH traversal instead of ordered
    bool sahAllAxes = false;          // bvh-sah, bvh-buckets: try x, y and z, not only the longest axis
};

// Throws rtlab::Error with the list of valid names when spec.name is unknown.
std::unique_ptr<Accelerator> makeAccelerator(const AcceleratorSpec& spec);

// The names makeAccelerator accepts in this executable, for help texts and errors.
std::string acceleratorNames();

}  // namespace rtlab
