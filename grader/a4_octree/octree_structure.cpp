#include "grader/a4_octree/octree_structure.h"

#include "grader/a4_octree/octree_oracle.h"
#include "grader/kit/truth_table.h"

#include <algorithm>

namespace rtlab::grader {
namespace {

std::string listOf(const std::vector<uint32_t>& prims) {
    std::string text;
    for (size_t i = 0; i < prims.size() && i < 6; ++i) text += (i ? ", " : "") + std::to_string(prims[i]);
    return text + (prims.size() > 6 ? ", ..." : "");
}

// The primitives that surely and possibly overlap a node's box, among those that possibly
// reached its parent (a primitive the parent cannot hold is in none of its children).
struct Reach {
    std::vector<uint32_t> sure, possible;  // increasing
};

class Checker {
public:
    Checker(const Octree& octree, const Scene& scene, const OctreeOptions& options, OctreeStructureReport& report)
        : octree_(octree), scene_(scene), options_(options), report_(report), slack_(overlapSlack(octree.root)) {}

    void run() {
        Bounds3f bounds;
        Reach root;
        for (uint32_t prim = 0; prim < scene_.primitiveCount(); ++prim)
            if (isPlaceable(scene_.primitiveBounds(prim))) {
                bounds.extend(scene_.primitiveBounds(prim));
                root.possible.push_back(prim);
            }
        root.sure = root.possible;  // the root holds every placeable primitive, untested
        Bounds3f expected = expectedRootBox(bounds);
        if (!(octree_.root == expected)) {
            problem("the root box is " + describeBox(octree_.root) + "; octreeRootBox of the primitives' bounds " + describeBox(bounds) +
                    " is " + describeBox(expected));
            return;
        }
        if (octree_.nodes.empty()) {
            problem("the octree has no nodes (an empty scene still has its root, a leaf)");
            return;
        }
        node(0, octree_.root, 0, root);
        if (report_.problemCount > 0) return;
        if (nextBlock_ != octree_.nodes.size())
            problem(std::to_string(octree_.nodes.size() - nextBlock_) + " nodes at the end of the array belong to no parent");
        if (nextPrim_ != octree_.primIndices.size())
            problem("primIndices has " + std::to_string(octree_.primIndices.size() - nextPrim_) + " entries after the last leaf's list");
    }

private:
    void problem(const std::string& text) {
        if (report_.problems.size() < 5) report_.problems.push_back(text);
        ++report_.problemCount;
    }

    // A primitive the build deals to a node's box: surely when it overlaps even the box shrunk by
    // the slack (a box: the box itself), possibly when it overlaps it grown by the slack; the
    // build's insertionBox lies between.
    Overlap overlap(uint32_t prim, const Bounds3f& box) const {
        if (options_.insertion == OctreeInsertion::Exact && !scene_.isSphere(prim))
            return triangleBoxOverlap(scene_.triangleVertices(prim), box, slack_);
        const Bounds3f& bounds = scene_.primitiveBounds(prim);
        if (boxesOverlap(bounds, box)) return Overlap::Yes;
        Bounds3f grown(box.lower - Vec3(float(slack_)), box.upper + Vec3(float(slack_)));
        return boxesOverlap(bounds, grown) ? Overlap::Unsure : Overlap::No;
    }

    Reach reachOf(const Bounds3f& box, const std::vector<uint32_t>& candidates) {
        Reach reach;
        for (uint32_t prim : candidates) {
            Overlap o = overlap(prim, box);
            if (o == Overlap::Yes) reach.sure.push_back(prim);
            if (o != Overlap::No) reach.possible.push_back(prim);
            if (o == Overlap::Unsure) ++report_.unsure;
        }
        return reach;
    }

    // How many of box's children every one of prims may overlap.
    int childrenHoldingAll(const Bounds3f& box, const std::vector<uint32_t>& prims) const {
        int count = 0;
        for (int k = 0; k < kOctreeChildren; ++k) {
            Bounds3f child = expectedChildBox(box, k);
            count += std::all_of(prims.begin(), prims.end(), [&](uint32_t p) { return overlap(p, child) != Overlap::No; }) ? 1 : 0;
        }
        return count;
    }

    // Written only when there is a problem: formatting every node's box took longer than checking it.
    static std::string describeNode(uint32_t index, int depth, const Bounds3f& box) {
        return "node " + std::to_string(index) + " (depth " + std::to_string(depth) + ", box " + describeBox(box) + ")";
    }

    void node(uint32_t index, const Bounds3f& box, int depth, const Reach& reach) {
        const OctreeNode& n = octree_.nodes[index];
        report_.depth = std::max(report_.depth, depth);
        if (n.isLeaf()) return leaf(index, n, box, depth, reach);
        auto where = [&] { return describeNode(index, depth, box); };
        if (depth >= options_.maxDepth) return problem(where() + " is split, but it lies at maxDepth " + std::to_string(options_.maxDepth));
        if (n.firstChild != nextBlock_)
            return problem(where() + ": its children start at node " + std::to_string(n.firstChild) + "; the depth-first layout puts them at " +
                           std::to_string(nextBlock_));
        if (uint64_t(n.firstChild) + kOctreeChildren > octree_.nodes.size())
            return problem(where() + ": its children run past the end of the node array");
        nextBlock_ += kOctreeChildren;
        if (n.primCount < reach.sure.size() || n.primCount > reach.possible.size())
            problem(where() + " counts " + std::to_string(n.primCount) + " primitives; " + std::to_string(reach.sure.size()) +
                    (reach.sure.size() == reach.possible.size() ? "" : " to " + std::to_string(reach.possible.size())) + " overlap it");
        if (n.primCount <= options_.maxPrims)
            problem(where() + " holds " + std::to_string(n.primCount) + " primitives, at most maxPrims = " + std::to_string(options_.maxPrims) +
                    ": it must be a leaf");
        int holdingAll = 0;
        for (int k = 0; k < kOctreeChildren; ++k) holdingAll += octree_.nodes[n.firstChild + k].primCount == n.primCount ? 1 : 0;
        if (holdingAll >= 2)
            problem(where() + ": " + std::to_string(holdingAll) + " of its children hold all its " + std::to_string(n.primCount) +
                    " primitives, so the memory rule makes it a leaf");
        if (report_.problems.size() >= 5) return;
        for (int k = 0; k < kOctreeChildren; ++k) {
            Bounds3f child = expectedChildBox(box, k);
            node(n.firstChild + k, child, depth + 1, reachOf(child, reach.possible));
        }
    }

    void leaf(uint32_t index, const OctreeNode& n, const Bounds3f& box, int depth, const Reach& reach) {
        ++report_.leaves;
        auto where = [&] { return describeNode(index, depth, box); };
        if (n.primStart != nextPrim_)
            return problem(where() + ": its list starts at " + std::to_string(n.primStart) + " in primIndices; the leaves before it end at " +
                           std::to_string(nextPrim_));
        if (uint64_t(n.primStart) + n.primCount > octree_.primIndices.size()) return problem(where() + ": its list runs past the end of primIndices");
        nextPrim_ += n.primCount;
        std::vector<uint32_t> list(octree_.primIndices.begin() + n.primStart, octree_.primIndices.begin() + n.primStart + n.primCount);
        if (std::adjacent_find(list.begin(), list.end(), std::greater_equal<uint32_t>()) != list.end())
            return problem(where() + ": its primitives " + listOf(list) + " are not in increasing order");
        std::vector<uint32_t> extra, missing;
        std::set_difference(list.begin(), list.end(), reach.possible.begin(), reach.possible.end(), std::back_inserter(extra));
        std::set_difference(reach.sure.begin(), reach.sure.end(), list.begin(), list.end(), std::back_inserter(missing));
        if (!missing.empty()) problem(where() + " misses the primitives " + listOf(missing) + ", which overlap it");
        if (!extra.empty()) problem(where() + " lists the primitives " + listOf(extra) + ", which do not overlap it");
        if (!missing.empty() || !extra.empty()) return;
        if (list.size() > options_.maxPrims && depth < options_.maxDepth && childrenHoldingAll(box, list) < 2)
            problem(where() + " is a leaf of " + std::to_string(list.size()) + " primitives, more than maxPrims = " +
                    std::to_string(options_.maxPrims) + " above maxDepth " + std::to_string(options_.maxDepth) +
                    ", and its split would separate them: it must be split");
    }

    const Octree& octree_;
    const Scene& scene_;
    const OctreeOptions& options_;
    OctreeStructureReport& report_;
    double slack_;
    uint32_t nextBlock_ = 1;
    uint64_t nextPrim_ = 0;
};

}  // namespace

OctreeStructureReport checkOctreeStructure(const Octree& octree, const Scene& scene, const OctreeOptions& options) {
    OctreeStructureReport report;
    Checker(octree, scene, options, report).run();
    return report;
}

}  // namespace rtlab::grader
