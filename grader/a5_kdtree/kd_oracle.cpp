#include "grader/a5_kdtree/kd_oracle.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rtlab::grader {
namespace {

double area(const Bounds3f& b) {
    double dx = double(b.upper.x) - b.lower.x, dy = double(b.upper.y) - b.lower.y, dz = double(b.upper.z) - b.lower.z;
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

const char* const kAxisNames[] = {"x", "y", "z"};

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string describePlane(int axis, float position, KdSide planarSide) {
    return std::string(kAxisNames[axis]) + " = " + number(position) + (planarSide == KdSide::Above ? " (planar above)" : "");
}

std::string describeBox(const Bounds3f& b) {
    std::string text;
    for (int a = 0; a < 3; ++a) text += (a ? " x [" : std::string("[")) + number(b.lower[a]) + ", " + number(b.upper[a]) + "]";
    return text;
}

std::string listOf(const std::vector<uint32_t>& ids) {
    std::string text;
    for (size_t i = 0; i < ids.size() && i < 8; ++i) text += (i ? ", " : "") + std::to_string(ids[i]);
    return ids.size() > 8 ? text + ", ... (" + std::to_string(ids.size()) + ")" : text;
}

// One pass over the tree in depth-first order, comparing each node with what the rules make of
// the primitives the classification sends to it.
class TreeCheck {
public:
    TreeCheck(const KdTree& tree, std::span<const Bounds3f> primBounds, const KdTreeOptions& options, KdTreeReport& report)
        : tree_(tree), primBounds_(primBounds), options_(options), report_(report) {}

    // Checks the subtree at the next node in depth-first order; false once the layout is broken
    // (the rest cannot be located).
    bool node(const Bounds3f& box, const std::vector<uint32_t>& prims, int depth, int badRefines, bool judged) {
        if (next_ >= tree_.nodes.size()) return fail("the tree ends before a node it refers to (node " + std::to_string(next_) + ")");
        if (depth > kKdMaxDepthLimit) return fail("deeper than " + std::to_string(kKdMaxDepthLimit) + " levels: no traversal stack holds it");
        uint32_t index = next_++;
        const KdNode& node = tree_.nodes[index];
        report_.depth = std::max(report_.depth, depth);
        std::string where = "node " + std::to_string(index) + " (depth " + std::to_string(depth) + ", " + std::to_string(prims.size()) +
                            " primitives, box " + describeBox(box) + ")";
        KdSplit best;
        if (judged && prims.size() > options_.maxPrims && depth < options_.maxDepth)
            best = kdOracleSplit(box, prims, primBounds_, options_.costs);
        KdNodeDecision decision = kdOracleDecision(uint32_t(prims.size()), depth, best, badRefines, options_);
        if (node.isLeaf()) {
            if (judged && !decision.leaf) {
                note(where + " is a leaf; the rules split it at " + describePlane(best.axis, best.position, best.planarSide) + " (cost " +
                     number(best.cost) + ", leaf cost " + number(options_.costs.intersection * double(prims.size())) + ")");
            }
            return leaf(node, where, prims, judged);
        }
        int axis = node.axis();
        float s = node.split();
        judged = judgePlane(where, box, axis, s, best, decision, judged);
        // Where primitives lying in the plane go is the best plane's rule; a plane that is not
        // the best has no rule, so its subtree is only checked for its layout and membership.
        KdSide planarSide = judged ? best.planarSide : KdSide::Below;
        std::vector<uint32_t> below, above;
        for (uint32_t prim : prims) {
            KdSide side = classify(primBounds_[prim], axis, s, planarSide);
            if (side != KdSide::Above) below.push_back(prim);
            if (side != KdSide::Below) above.push_back(prim);
        }
        Bounds3f belowBox = box, aboveBox = box;
        belowBox.upper[axis] = aboveBox.lower[axis] = s;
        if (!this->node(belowBox, below, depth + 1, decision.badRefines, judged)) return false;
        if (node.aboveChild() != next_)
            return fail(where + ": its above child is " + std::to_string(node.aboveChild()) + ", but its below child's subtree ends at node " +
                        std::to_string(next_) + " (depth-first order, below child first)");
        return this->node(aboveBox, above, depth + 1, decision.badRefines, judged);
    }

    bool finished() {
        if (next_ != tree_.nodes.size()) note(std::to_string(tree_.nodes.size() - next_) + " nodes are not reached from the root");
        if (primCursor_ != tree_.primIndices.size())
            note("primIndices has " + std::to_string(tree_.primIndices.size() - primCursor_) + " entries no leaf lists");
        return true;
    }

    void note(const std::string& problem) {
        if (report_.problems.size() < 8) report_.problems.push_back(problem);
        ++report_.problemCount;
    }

private:
    // Whether an interior node's plane is the one the rules choose; notes why not. Below a plane
    // that is not, nothing is judged any more, only the layout and the membership are checked.
    bool judgePlane(const std::string& where, const Bounds3f& box, int axis, float s, const KdSplit& best, const KdNodeDecision& decision,
                    bool judged) {
        std::string plane = std::string(kAxisNames[axis]) + " = " + number(s);
        if (!(box.lower[axis] < s && s < box.upper[axis])) {
            note(where + ": the plane " + plane + " is not strictly inside the node");
            return false;
        }
        if (!judged) return false;
        if (decision.leaf) {
            note(where + " is split at " + plane + "; the rules make it a leaf" +
                 (best.found() ? " (best cost " + number(best.cost) + ", " + std::to_string(decision.badRefines) + " bad refines)"
                               : " (no plane lies strictly inside it)"));
            return false;
        }
        if (axis != best.axis || s != best.position) {
            note(where + " is split at " + plane + "; the best plane is " + describePlane(best.axis, best.position, best.planarSide) + " (cost " +
                 number(best.cost) + ")");
            return false;
        }
        return true;
    }

    static KdSide classify(const Bounds3f& box, int axis, float s, KdSide planarSide) {
        bool inPlane = box.lower[axis] == s && box.upper[axis] == s;
        bool below = box.lower[axis] < s || (inPlane && planarSide == KdSide::Below);
        bool above = box.upper[axis] > s || (inPlane && planarSide == KdSide::Above);
        return below && above ? KdSide::Both : below ? KdSide::Below : KdSide::Above;
    }

    bool leaf(const KdNode& node, const std::string& where, const std::vector<uint32_t>& prims, bool judged) {
        ++report_.leaves;
        report_.references += node.primCount();
        if (node.firstPrim() != primCursor_)
            return fail(where + ": a leaf whose list starts at " + std::to_string(node.firstPrim()) + " instead of " + std::to_string(primCursor_) +
                        " (leaves list their primitives one after the other, in depth-first order)");
        if (uint64_t(node.firstPrim()) + node.primCount() > tree_.primIndices.size())
            return fail(where + ": a leaf's list runs past the end of primIndices");
        primCursor_ += node.primCount();
        std::vector<uint32_t> got(tree_.primIndices.begin() + node.firstPrim(), tree_.primIndices.begin() + primCursor_);
        if (got == prims) return true;
        std::vector<uint32_t> missing, extra, sortedGot = got;
        std::sort(sortedGot.begin(), sortedGot.end());
        std::set_difference(prims.begin(), prims.end(), sortedGot.begin(), sortedGot.end(), std::back_inserter(missing));
        std::set_difference(sortedGot.begin(), sortedGot.end(), prims.begin(), prims.end(), std::back_inserter(extra));
        std::string what = missing.empty() && extra.empty() ? "the right primitives, not in increasing order (or listed twice)"
                                                            : (missing.empty() ? "" : "missing " + listOf(missing)) +
                                                                  (!missing.empty() && !extra.empty() ? "; " : "") +
                                                                  (extra.empty() ? "" : "extra " + listOf(extra));
        note(where + ": " + what + (judged ? "" : " (below a plane that is not the best one)"));
        return true;
    }

    bool fail(const std::string& problem) {
        note(problem);
        return false;
    }

    const KdTree& tree_;
    std::span<const Bounds3f> primBounds_;
    const KdTreeOptions& options_;
    KdTreeReport& report_;
    uint32_t next_ = 0;
    size_t primCursor_ = 0;
};

}  // namespace

double kdPlaneCost(const Bounds3f& node, int axis, float position, uint32_t nBelow, uint32_t nAbove, const KdCosts& costs) {
    double total = area(node);
    if (!(total > 0.0)) return std::numeric_limits<double>::infinity();
    Bounds3f below = node, above = node;
    below.upper[axis] = position;
    above.lower[axis] = position;
    double bonus = (nBelow == 0 || nAbove == 0) ? costs.emptyBonus : 0.0;
    return costs.traversal + costs.intersection * (1.0 - bonus) * (area(below) / total * nBelow + area(above) / total * nAbove);
}

KdSplit kdOracleSplit(const Bounds3f& box, std::span<const uint32_t> prims, std::span<const Bounds3f> primBounds, const KdCosts& costs) {
    KdSplit best;
    for (int axis = 0; axis < 3; ++axis) {
        // Counting instead of sweeping: at a candidate p, nLess = #(lower < p), nMore =
        // #(upper > p) and nPlanar = #(lower == upper == p), each a binary search.
        std::vector<float> lowers, uppers, planars;
        for (uint32_t prim : prims) {
            float lo = primBounds[prim].lower[axis], hi = primBounds[prim].upper[axis];
            lowers.push_back(lo);
            uppers.push_back(hi);
            if (lo == hi) planars.push_back(lo);
        }
        std::sort(lowers.begin(), lowers.end());
        std::sort(uppers.begin(), uppers.end());
        std::sort(planars.begin(), planars.end());
        std::vector<float> candidates;
        for (float p : lowers)
            if (box.lower[axis] < p && p < box.upper[axis]) candidates.push_back(p);
        for (float p : uppers)
            if (box.lower[axis] < p && p < box.upper[axis]) candidates.push_back(p);
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (float p : candidates) {
            auto nLess = uint32_t(std::lower_bound(lowers.begin(), lowers.end(), p) - lowers.begin());
            auto nMore = uint32_t(uppers.end() - std::upper_bound(uppers.begin(), uppers.end(), p));
            auto inPlane = std::equal_range(planars.begin(), planars.end(), p);
            auto nPlanar = uint32_t(inPlane.second - inPlane.first);
            for (KdSide side : {KdSide::Below, KdSide::Above}) {
                uint32_t nBelow = nLess + (side == KdSide::Below ? nPlanar : 0), nAbove = nMore + (side == KdSide::Above ? nPlanar : 0);
                double cost = kdPlaneCost(box, axis, p, nBelow, nAbove, costs);
                if (cost < best.cost) best = KdSplit{axis, p, side, cost, nBelow, nAbove};
            }
        }
    }
    return best;
}

int kdOracleMaxDepth(uint64_t primCount) {
    int log2Floor = primCount <= 1 ? 0 : 63 - std::countl_zero(primCount);
    return std::min(kKdMaxDepthLimit, int(std::lround(8.0 + 1.3 * log2Floor)));
}

KdNodeDecision kdOracleDecision(uint32_t primCount, int depth, const KdSplit& best, int badRefines, const KdTreeOptions& options) {
    if (primCount <= options.maxPrims || depth >= options.maxDepth || !best.found()) return {true, badRefines};
    double leafCost = options.costs.intersection * primCount;
    int refines = badRefines + (best.cost > leafCost ? 1 : 0);
    return {(best.cost > 4.0 * leafCost && primCount < 16) || refines >= kKdMaxBadRefines, refines};
}

double kdTreeCost(const KdTree& tree, const KdCosts& costs) {
    if (tree.nodes.empty()) return 0.0;
    double rootArea = area(tree.bounds);
    if (!(rootArea > 0.0)) return costs.intersection * double(tree.primIndices.size());
    double cost = 0.0;
    // Depth first with each node's box; the tree was checked, so indices are in range.
    std::vector<std::pair<uint32_t, Bounds3f>> stack{{0u, tree.bounds}};
    while (!stack.empty()) {
        auto [index, box] = stack.back();
        stack.pop_back();
        const KdNode& node = tree.nodes[index];
        if (node.isLeaf()) {
            cost += costs.intersection * node.primCount() * area(box) / rootArea;
            continue;
        }
        cost += costs.traversal * area(box) / rootArea;
        Bounds3f below = box, above = box;
        below.upper[node.axis()] = above.lower[node.axis()] = node.split();
        stack.push_back({node.aboveChild(), above});
        stack.push_back({index + 1, below});
    }
    return cost;
}

KdTreeReport checkKdTree(const KdTree& tree, std::span<const Bounds3f> primBounds, const KdTreeOptions& options) {
    KdTreeReport report;
    std::vector<uint32_t> prims;
    Bounds3f bounds;
    for (uint32_t prim = 0; prim < primBounds.size(); ++prim)
        if (isPlaceable(primBounds[prim])) {
            prims.push_back(prim);
            bounds.extend(primBounds[prim]);
        }
    KdTreeOptions resolved = options;
    resolved.maxDepth = options.maxDepth > 0 ? options.maxDepth : kdOracleMaxDepth(prims.size());
    report.maxDepth = resolved.maxDepth;
    TreeCheck check(tree, primBounds, resolved, report);
    if (prims.empty()) {
        if (!tree.nodes.empty()) check.note("no primitive is placeable, so the tree must have no nodes; it has " + std::to_string(tree.nodes.size()));
        return report;
    }
    if (!(tree.bounds == bounds))
        check.note("tree.bounds is " + describeBox(tree.bounds) + "; the placeable primitives' union is " + describeBox(bounds));
    if (tree.maxDepth != resolved.maxDepth)
        check.note("tree.maxDepth is " + std::to_string(tree.maxDepth) + "; the rule gives " + std::to_string(resolved.maxDepth));
    if (check.node(bounds, prims, 0, 0, true)) check.finished();
    return report;
}

}  // namespace rtlab::grader
