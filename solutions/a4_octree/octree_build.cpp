// Reference solution: the octree's boxes and its recursive build (docs/a4-octree.md#building).
#include "framework/interface/a4_octree.h"

#include <algorithm>

namespace rtlab {

namespace {

bool boxesOverlap(const Bounds3f& a, const Bounds3f& b) {
    for (int axis = 0; axis < 3; ++axis)
        if (!(a.lower[axis] <= b.upper[axis] && a.upper[axis] >= b.lower[axis])) return false;
    return true;
}

class OctreeBuilder {
public:
    OctreeBuilder(const OctreeInput& input, const OctreeOptions& options, Octree& octree)
        : input_(input), options_(options), octree_(octree) {}

    // Makes node `index` (already in the array) over box with these primitives.
    void build(uint32_t index, const Bounds3f& box, std::vector<uint32_t> prims, int depth) {
        octree_.nodes[index].primCount = static_cast<uint32_t>(prims.size());
        if (prims.size() <= options_.maxPrims || depth == options_.maxDepth) return makeLeaf(index, prims);
        std::array<std::vector<uint32_t>, kOctreeChildren> children;
        int holdingAll = 0;
        for (int k = 0; k < kOctreeChildren; ++k) {
            // Slightly grown, so that rounding never leaves out a primitive touching the child.
            Bounds3f child = insertionBox(childBox(box, k));
            for (uint32_t prim : prims)
                if (overlaps(prim, child)) children[k].push_back(prim);
            holdingAll += children[k].size() == prims.size() ? 1 : 0;
        }
        // Primitives that all reach into two children at once are not separated by this split,
        // nor by any below it on that side: they would be copied at every level.
        if (holdingAll >= 2) return makeLeaf(index, prims);
        prims = {};  // the children have them now
        // Index, not a reference: appending the children may move the array.
        uint32_t first = static_cast<uint32_t>(octree_.nodes.size());
        octree_.nodes[index].firstChild = first;
        octree_.nodes.resize(first + kOctreeChildren);
        for (int k = 0; k < kOctreeChildren; ++k) build(first + k, childBox(box, k), std::move(children[k]), depth + 1);
    }

private:
    bool overlaps(uint32_t prim, const Bounds3f& box) const {
        if (options_.insertion == OctreeInsertion::Exact && prim < input_.triangles.size()) {
            const std::array<Vec3, 3>& t = input_.triangles[prim];
            return triangleOverlapsBox(t[0], t[1], t[2], box);
        }
        return boxesOverlap(input_.bounds[prim], box);
    }

    void makeLeaf(uint32_t index, const std::vector<uint32_t>& prims) {
        octree_.nodes[index].primStart = static_cast<uint32_t>(octree_.primIndices.size());
        octree_.primIndices.insert(octree_.primIndices.end(), prims.begin(), prims.end());
    }

    const OctreeInput& input_;
    const OctreeOptions& options_;
    Octree& octree_;
};

}  // namespace

Bounds3f octreeRootBox(const Bounds3f& bounds) {
    if (bounds.isEmpty()) return Bounds3f(Vec3(0.0f));
    Vec3 extent = bounds.diagonal();
    float half = 0.5f * std::max({extent.x, extent.y, extent.z});
    Vec3 centre = bounds.centre();
    Bounds3f cube;
    cube.lower = centre - Vec3(half);
    cube.upper = centre + Vec3(half);
    // The centre and the half side are rounded: the cube may miss the bounds by an ulp, and a
    // primitive on the bounds would then lie outside the root.
    cube.extend(bounds);
    return cube;
}

Bounds3f childBox(const Bounds3f& box, int child) {
    // One mid for all eight children, so that neighbours share their face bit for bit.
    Vec3 mid = box.centre();
    Bounds3f result = box;
    for (int axis = 0; axis < 3; ++axis) {
        if (child & (4 >> axis)) result.lower[axis] = mid[axis];
        else result.upper[axis] = mid[axis];
    }
    return result;
}

int childIndex(const Vec3& p, const Vec3& mid) {
    return (p.x >= mid.x ? 4 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 1 : 0);
}

Octree buildOctree(const OctreeInput& input, const OctreeOptions& options) {
    Octree octree;
    Bounds3f bounds;
    std::vector<uint32_t> prims;
    for (uint32_t prim = 0; prim < input.bounds.size(); ++prim)
        if (isPlaceable(input.bounds[prim])) {
            bounds.extend(input.bounds[prim]);
            prims.push_back(prim);
        }
    octree.root = octreeRootBox(bounds);
    octree.nodes.resize(1);
    OctreeBuilder(input, options, octree).build(0, octree.root, std::move(prims), 0);
    return octree;
}

}  // namespace rtlab
