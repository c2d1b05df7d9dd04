// Reference solution: closest-hit and any-hit traversal of the octree, front to back with
// Revelles' parametric walk (docs/a4-octree.md#traversal).
#include "framework/interface/a4_octree.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

// One query's walk: the closest-hit form when hit is given, the any-hit form otherwise.
class OctreeWalk {
public:
    OctreeWalk(const Octree& octree, Traversal& traversal, Hit* hit)
        : octree_(octree), traversal_(traversal), hit_(hit), mirrored_(mirrorRay(octree.root, traversal.ray())) {}

    // Walks the octree; for any-hit, returns whether a primitive blocks the ray.
    bool run() {
        if (octree_.nodes.empty()) return false;  // never built: not even a root
        NodeSpan span = rootSpan(octree_.root, mirrored_.ray);
        // NaN (from a NaN origin or direction) would slip through max and min: a miss.
        if (glm::any(glm::isnan(span.t0)) || glm::any(glm::isnan(span.t1))) return false;
        float enter = std::max({span.t0.x, span.t0.y, span.t0.z}), exit = std::min({span.t1.x, span.t1.y, span.t1.z});
        if (!(enter <= exit && exit >= tMin() && enter <= tMax())) return false;
        walk(0, octree_.root, span);
        return blocked_;
    }

private:
    float tMin() const { return traversal_.ray().tMin; }
    // The farthest hit that still counts: the closest so far, or the end of the segment.
    float tMax() const { return hit_ ? hit_->t : traversal_.ray().tMax; }

    // Walks one node; returns true when the whole traversal is over.
    bool walk(uint32_t index, const Bounds3f& box, const NodeSpan& span) {
        float exit = std::min({span.t1.x, span.t1.y, span.t1.z});
        // The node lies wholly before the segment's start (the origin is past it).
        if (exit < tMin()) return false;
        const OctreeNode& node = octree_.nodes[index];
        if (node.isLeaf()) return visitLeaf(index, node, exit);
        Vec3 tm = midParameters(mirrored_.ray, span, box);
        for (int k = firstNode(span.t0, tm); k != kOctreeEnd;) {
            // The child spans from the parent's entry to the mid-plane on an axis where it is
            // the lower half, from the mid-plane to the parent's exit where it is the upper.
            NodeSpan child = span;
            for (int axis = 0; axis < 3; ++axis) {
                if (k & (4 >> axis)) child.t0[axis] = tm[axis];
                else child.t1[axis] = tm[axis];
            }
            // k numbers the mirrored octree's children; k ^ mask is the real one.
            if (walk(node.firstChild + uint32_t(k ^ mirrored_.mask), childBox(box, k), child)) return true;
            k = nextNode(k, child.t1);
        }
        return false;
    }

    bool visitLeaf(uint32_t index, const OctreeNode& leaf, float exit) {
        traversal_.enterLeaf(index);
        for (uint32_t i = leaf.primStart; i < leaf.primStart + leaf.primCount; ++i) {
            uint32_t prim = octree_.primIndices[i];
            if (hit_) traversal_.intersectOnce(prim, *hit_);
            else if (traversal_.occludesOnce(prim)) return blocked_ = true;
        }
        // Every later leaf starts where this one ends: a hit (or the segment's end) no farther
        // than that cannot be beaten. A hit beyond it stays a candidate.
        return tMax() <= exit;
    }

    const Octree& octree_;
    Traversal& traversal_;
    Hit* hit_;
    MirroredRay mirrored_;
    bool blocked_ = false;
};

}  // namespace

bool intersectOctree(const Octree& octree, Traversal& traversal, Hit& hit) {
    OctreeWalk(octree, traversal, &hit).run();
    return hit.found();
}

bool occludedOctree(const Octree& octree, Traversal& traversal) { return OctreeWalk(octree, traversal, nullptr).run(); }

}  // namespace rtlab
