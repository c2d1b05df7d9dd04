#include "grader/a4_octree/octree_visit_order.h"

#include "framework/oracle/oracle.h"
#include "grader/kit/hit_judge.h"
#include "grader/a4_octree/octree_oracle.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rtlab::grader {
namespace {

// Hits closer than this to a triangle's edge (in barycentric units) may be misses in float.
constexpr double kHitEdgeMargin = 1e-4;
// Ray parameters this close (relative), on top of the slack's share, may be ordered either way
// by a float walk.
constexpr double kRelativeT = 1e-5;

struct Span {
    double enter, exit;
};

// Where the ray enters and leaves the closed box grown by `grow` (negative: shrunk), unclipped
// by the segment, or nullopt when it misses it.
std::optional<Span> slabs(const Bounds3f& box, const OracleRay& ray, double grow) {
    Span s{-INFINITY, INFINITY};
    for (int a = 0; a < 3; ++a) {
        double lo = box.lower[a] - grow, hi = box.upper[a] + grow, o = ray.origin[a], d = ray.direction[a];
        if (lo > hi) return std::nullopt;
        if (d == 0.0) {
            if (o < lo || o > hi) return std::nullopt;
            continue;
        }
        double t0 = (lo - o) / d, t1 = (hi - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        s.enter = std::max(s.enter, t0);
        s.exit = std::min(s.exit, t1);
    }
    if (!(s.enter <= s.exit)) return std::nullopt;
    return s;
}

struct Crossed {
    uint32_t leaf;
    Span span;
};

class LeafOrder {
public:
    LeafOrder(const Octree& octree, const std::vector<Bounds3f>& boxes, const Scene& scene, const Ray& ray)
        : octree_(octree), boxes_(boxes), scene_(scene), ray_(OracleRay::from(ray)), slack_(overlapSlack(octree.root)) {
        double length = glm::length(ray_.direction);
        tolerance_ = length > 0 ? slack_ / length : INFINITY;
    }

    std::optional<std::vector<uint32_t>> run() {
        if (octree_.nodes.empty() || !std::isfinite(tolerance_)) return std::nullopt;
        collect(0);
        if (unsure_) return std::nullopt;
        std::sort(crossed_.begin(), crossed_.end(), [](const Crossed& a, const Crossed& b) { return a.span.enter < b.span.enter; });
        for (size_t i = 1; i < crossed_.size(); ++i)
            if (near(crossed_[i].span.enter, crossed_[i - 1].span.enter)) return std::nullopt;
        // The walk up to the leaf after which nothing nearer can come.
        Oracle oracle(scene_);
        double best = ray_.tMax;
        std::vector<uint32_t> order;
        for (const Crossed& c : crossed_) {
            order.push_back(c.leaf);
            const OctreeNode& leaf = octree_.nodes[c.leaf];
            for (uint32_t i = leaf.primStart; i < leaf.primStart + leaf.primCount; ++i)
                // Hits up to the margin outside an edge too: float may find one there.
                if (std::optional<OracleHit> hit = oracle.intersect(octree_.primIndices[i], ray_, kHitEdgeMargin)) {
                    if (hit->edgeMargin < kHitEdgeMargin) return std::nullopt;
                    best = std::min(best, hit->t);
                }
            if (near(best, c.span.exit)) return std::nullopt;
            if (best <= c.span.exit) break;
        }
        return order;
    }

private:
    bool near(double a, double b) const {
        return std::abs(a - b) < tolerance_ + kRelativeT * std::max(std::abs(a), std::abs(b));
    }

    // The leaves the segment crosses, below node; any leaf it may or may not cross makes the
    // ray unsure.
    void collect(uint32_t node) {
        const Bounds3f& box = boxes_[node];
        std::optional<Span> grown = slabs(box, ray_, slack_);
        if (!grown || grown->exit < ray_.tMin - tolerance_ || grown->enter > ray_.tMax + tolerance_) return;
        const OctreeNode& n = octree_.nodes[node];
        if (!n.isLeaf()) {
            for (int k = 0; k < kOctreeChildren; ++k) collect(n.firstChild + k);
            return;
        }
        std::optional<Span> shrunk = slabs(box, ray_, -slack_);
        std::optional<Span> exact = slabs(box, ray_, 0.0);
        if (!shrunk || !exact || shrunk->exit < ray_.tMin + tolerance_ || shrunk->enter > ray_.tMax - tolerance_) {
            unsure_ = true;
            return;
        }
        crossed_.push_back({node, *exact});
    }

    const Octree& octree_;
    const std::vector<Bounds3f>& boxes_;
    const Scene& scene_;
    OracleRay ray_;
    double slack_, tolerance_ = 0.0;
    bool unsure_ = false;
    std::vector<Crossed> crossed_;
};

std::string describeLeaves(const std::vector<uint32_t>& leaves, size_t from) {
    std::string text;
    for (size_t i = from; i < leaves.size() && i < from + 4; ++i) text += (i > from ? ", " : "") + std::to_string(leaves[i]);
    return text.empty() ? "nothing" : text + (leaves.size() > from + 4 ? ", ..." : "");
}

}  // namespace

std::vector<Bounds3f> octreeNodeBoxes(const Octree& octree) {
    std::vector<Bounds3f> boxes(octree.nodes.size());
    if (boxes.empty()) return boxes;
    boxes[0] = octree.root;
    // Parents come before their children in the pinned layout.
    for (size_t i = 0; i < octree.nodes.size(); ++i)
        if (!octree.nodes[i].isLeaf())
            for (int k = 0; k < kOctreeChildren; ++k) boxes[octree.nodes[i].firstChild + k] = expectedChildBox(boxes[i], k);
    return boxes;
}

std::optional<std::vector<uint32_t>> expectedLeafOrder(const Octree& octree, const std::vector<Bounds3f>& nodeBoxes, const Scene& scene,
                                                       const Ray& ray) {
    return LeafOrder(octree, nodeBoxes, scene, ray).run();
}

VisitOrderVerdict judgeOctreeVisits(const Octree& octree, const Scene& scene, const std::vector<Ray>& rays,
                                    const std::vector<std::vector<uint32_t>>& entered) {
    VisitOrderVerdict verdict;
    std::vector<Bounds3f> boxes = octreeNodeBoxes(octree);
    for (size_t r = 0; r < rays.size(); ++r) {
        std::optional<std::vector<uint32_t>> expected = expectedLeafOrder(octree, boxes, scene, rays[r]);
        if (!expected) continue;
        ++verdict.graded;
        const std::vector<uint32_t>& got = entered[r];
        if (got == *expected) continue;
        size_t k = 0;
        while (k < got.size() && k < expected->size() && got[k] == (*expected)[k]) ++k;
        std::string what = expected->empty()        ? "entered " + describeLeaves(got, 0) + "; the segment crosses no leaf"
                           : k == expected->size() ? "entered " + describeLeaves(got, k) + " after the last leaf it needed (node " +
                                                         std::to_string(expected->back()) + "), where the closest hit was already found"
                           : k == got.size()       ? "stopped after " + std::to_string(k) + " leaves; it had still to enter " +
                                                   describeLeaves(*expected, k)
                                                 : "leaf " + std::to_string(k) + " of its walk is node " + std::to_string(got[k]) +
                                                   ", front to back it is node " + std::to_string((*expected)[k]);
        ++verdict.wrong;
        if (verdict.problems.size() >= 5) continue;
        verdict.problems.push_back(describeRay(rays[r]) + ": " + what);
        verdict.wrongRays.push_back(r);
    }
    return verdict;
}

}  // namespace rtlab::grader
