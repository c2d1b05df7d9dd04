// The grader's own statement of the KD-tree rules (docs/a5-kdtree.md), to judge a built tree
// without the reference solution: the plane cost, the best plane of a node found by counting
// (binary searches over sorted box ends, not the event sweep students write), the leaf rule, and
// a node-by-node check of a whole tree against them. Because the rules pin every choice, a tree
// that passes the check is the reference's, bit for bit.
#pragma once

#include "framework/interface/kdtree.h"

#include <span>
#include <string>
#include <vector>

namespace rtlab::grader {

// K_T + K_I (1 - eb) (SA_below/SA nBelow + SA_above/SA nAbove), areas in double; +inf for a node
// of area 0.
double kdPlaneCost(const Bounds3f& node, int axis, float position, uint32_t nBelow, uint32_t nAbove, const KdCosts& costs);

// The cheapest plane strictly inside box for the primitives prims (ids into primBounds), ties to
// the lower axis, the lower position, then planar below. axis -1 when there is none.
KdSplit kdOracleSplit(const Bounds3f& box, std::span<const uint32_t> prims, std::span<const Bounds3f> primBounds, const KdCosts& costs);

// pbrt's depth limit lround(8 + 1.3 floor(log2 N)), at most kKdMaxDepthLimit.
int kdOracleMaxDepth(uint64_t primCount);

// The leaf rule of docs/a5-kdtree.md#when-to-stop; maxDepth resolved.
KdNodeDecision kdOracleDecision(uint32_t primCount, int depth, const KdSplit& best, int badRefines, const KdTreeOptions& options);

// The tree's cost by the SAH (what the grader compares with the reference data):
// sum over interior nodes of K_T SA(n)/SA(root) plus sum over leaves of K_I |L| SA(L)/SA(root).
double kdTreeCost(const KdTree& tree, const KdCosts& costs);

struct KdTreeReport {
    std::vector<std::string> problems;  // empty: the tree the rules give
    size_t problemCount = 0;            // problems beyond the listed ones included
    size_t leaves = 0, references = 0;
    int depth = 0;
    int maxDepth = 0;                   // the limit the rule gives
};

// Checks a built tree node by node, in depth-first order: the root's box and depth limit; the
// layout (below child next, above child where its subtree begins, leaves' lists one after the
// other); every plane strictly inside its node; every leaf holding exactly the primitives the
// pinned classification sends there, in increasing order; every node a leaf or split exactly as
// the leaf rule and the best plane say. options.maxDepth 0 means the rule's limit.
KdTreeReport checkKdTree(const KdTree& tree, std::span<const Bounds3f> primBounds, const KdTreeOptions& options);

}  // namespace rtlab::grader
