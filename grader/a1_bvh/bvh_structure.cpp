#include "grader/a1_bvh/bvh_structure.h"

#include "framework/interface/a1_bvh.h"

#include <cmath>
#include <cstdio>

namespace rtlab::grader {
namespace {

class Problems {
public:
    explicit Problems(BvhStructureReport& report) : report_(report) {}
    void add(const std::string& text) {
        if (report_.problems.size() < 5) report_.problems.push_back(text);
        ++report_.problemCount;
    }

private:
    BvhStructureReport& report_;
};

std::string describe(const Bounds3f& b) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "[(%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g)]", b.lower.x, b.lower.y, b.lower.z,
                  b.upper.x, b.upper.y, b.upper.z);
    return buffer;
}

bool isFinite(const Bounds3f& b) {
    for (int axis = 0; axis < 3; ++axis)
        if (!std::isfinite(b.lower[axis]) || !std::isfinite(b.upper[axis])) return false;
    return true;
}

double surfaceArea(const Bounds3f& b) {
    if (b.isEmpty()) return 0.0;
    DVec3 d = DVec3(b.upper) - DVec3(b.lower);
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

}  // namespace

BvhStructureReport checkBvhStructure(const Bvh& bvh, const std::vector<Bounds3f>& primBounds, bool checkTight) {
    BvhStructureReport report;
    Problems problems(report);
    const size_t n = bvh.nodes.size();
    if (n == 0) {
        if (!primBounds.empty()) problems.add("the BVH has no nodes but there are " + std::to_string(primBounds.size()) + " primitives");
        return report;
    }
    std::vector<uint32_t> seenPrim(primBounds.size(), 0);
    std::vector<uint8_t> reached(n, 0);
    std::vector<Bounds3f> content(n);  // what each node really holds, filled bottom-up
    struct Entry {
        uint32_t node;
        int depth;
        bool expanded;
    };
    std::vector<Entry> stack{{0, 0, false}};
    while (!stack.empty() && report.problemCount < 1000) {
        Entry e = stack.back();
        stack.pop_back();
        const BvhNode& node = bvh.nodes[e.node];
        const std::string name = "node " + std::to_string(e.node);
        if (!e.expanded) {
            if (reached[e.node]++) {
                problems.add(name + " is reachable twice");
                continue;
            }
            report.depth = std::max(report.depth, e.depth);
            if (node.isLeaf()) {
                ++report.leaves;
                if (uint64_t(node.offset) + node.primCount > bvh.primIndices.size()) {
                    problems.add(name + ": leaf range [" + std::to_string(node.offset) + ", +" + std::to_string(node.primCount) +
                                 ") runs past primIndices (" + std::to_string(bvh.primIndices.size()) + ")");
                    continue;
                }
                for (uint32_t k = 0; k < node.primCount; ++k) {
                    uint32_t prim = bvh.primIndices[node.offset + k];
                    if (prim >= primBounds.size()) {
                        problems.add(name + " holds primitive " + std::to_string(prim) + ", which does not exist");
                        continue;
                    }
                    ++seenPrim[prim];
                    content[e.node].extend(primBounds[prim]);
                }
                continue;
            }
            uint32_t first = e.node + 1, second = node.offset;
            if (first >= n || second <= first || second >= n) {
                problems.add(name + ": interior node with children " + std::to_string(first) + " and " + std::to_string(second) +
                             " outside the layout (first child next, second after it, both below " + std::to_string(n) + ")");
                continue;
            }
            stack.push_back({e.node, e.depth, true});
            stack.push_back({second, e.depth + 1, false});
            stack.push_back({first, e.depth + 1, false});
        } else {
            content[e.node] = unionOf(content[e.node + 1], content[node.offset]);
            for (uint32_t child : {e.node + 1, node.offset})
                if (isFinite(bvh.nodes[child].bounds) && !node.bounds.contains(bvh.nodes[child].bounds))
                    problems.add(name + "'s box " + describe(node.bounds) + " does not contain child " + std::to_string(child) +
                                 "'s box " + describe(bvh.nodes[child].bounds));
        }
    }
    for (size_t i = 0; i < n; ++i) {
        if (!reached[i]) {
            problems.add("node " + std::to_string(i) + " is not reachable from the root");
            continue;
        }
        const BvhNode& node = bvh.nodes[i];
        // Primitives with NaN or infinite vertices (stress inputs) have no meaningful box.
        if (!isFinite(content[i])) continue;
        if (!node.bounds.contains(content[i]))
            problems.add("node " + std::to_string(i) + "'s box " + describe(node.bounds) + " does not contain its primitives " +
                         describe(content[i]));
        else if (checkTight && !(node.bounds == content[i]))
            problems.add("node " + std::to_string(i) + "'s box " + describe(node.bounds) + " is not tight (its primitives span " +
                         describe(content[i]) + ")");
    }
    for (size_t prim = 0; prim < seenPrim.size(); ++prim)
        if (seenPrim[prim] != 1)
            problems.add("primitive " + std::to_string(prim) + " is in " + std::to_string(seenPrim[prim]) + " leaves (must be exactly one)");
    if (report.depth >= kMaxBvhDepth)
        problems.add("depth " + std::to_string(report.depth) + " exceeds the traversal stack (" + std::to_string(kMaxBvhDepth) + ")");
    return report;
}

std::vector<std::string> oversizedLeaves(const Bvh& bvh, const std::vector<Bounds3f>& primBounds, int maxLeaf) {
    std::vector<std::string> problems;
    if (bvh.nodes.empty()) return problems;
    struct Entry {
        uint32_t node;
        int depth;
    };
    std::vector<Entry> stack{{0, 0}};
    while (!stack.empty()) {
        Entry e = stack.back();
        stack.pop_back();
        const BvhNode& node = bvh.nodes[e.node];
        if (!node.isLeaf()) {
            stack.push_back({node.offset, e.depth + 1});
            stack.push_back({e.node + 1, e.depth + 1});
            continue;
        }
        if (node.primCount <= maxLeaf || e.depth >= kMaxBvhDepth - 1) continue;
        Bounds3f centroids;
        for (uint32_t k = 0; k < node.primCount; ++k) centroids.extend(primBounds[bvh.primIndices[node.offset + k]].centre());
        if (centroids.lower == centroids.upper) continue;
        if (problems.size() < 5)
            problems.push_back("node " + std::to_string(e.node) + " is a leaf of " + std::to_string(node.primCount) +
                               " primitives, more than maxLeaf " + std::to_string(maxLeaf) + ", at depth " + std::to_string(e.depth) +
                               ", although their centroids differ " + describe(centroids) + ": it must be split");
    }
    return problems;
}

double graderSahCost(const Bvh& bvh) {
    if (bvh.nodes.empty()) return 0.0;
    double rootArea = surfaceArea(bvh.nodes[0].bounds);
    if (!(rootArea > 0.0)) return double(bvh.primIndices.size());
    double cost = 0.0;
    for (const BvhNode& node : bvh.nodes) {
        double share = surfaceArea(node.bounds) / rootArea;
        cost += node.isLeaf() ? double(node.primCount) * share : share;
    }
    return cost;
}

}  // namespace rtlab::grader
