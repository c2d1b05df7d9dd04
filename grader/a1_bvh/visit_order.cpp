#include "grader/a1_bvh/visit_order.h"

#include "framework/oracle/oracle.h"
#include "grader/kit/hit_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace rtlab::grader {
namespace {

// Boxes are grown and shrunk by this share of the scene's size to tell a sure hit or miss from
// one that float rounding may decide either way.
constexpr double kBoxEdgeSlack = 1e-5;
// A leaf entered this much (relative) beyond the closest hit so far is entered too far.
constexpr double kDistanceSlack = 1e-5;
// Hits closer than this to a triangle's edge (in barycentric units) may be misses in float.
constexpr double kHitEdgeMargin = 1e-4;

enum class BoxTest { Miss, Hit, Unsure };

// Where the ray's segment (tMin, tMax] enters box in double, or nullopt on a miss.
std::optional<double> entry(const Bounds3f& box, const OracleRay& ray, double grow) {
    double tNear = ray.tMin, tFar = ray.tMax;
    for (int a = 0; a < 3; ++a) {
        double lo = box.lower[a] - grow, hi = box.upper[a] + grow, o = ray.origin[a], d = ray.direction[a];
        if (lo > hi) return std::nullopt;  // shrunk past its thickness
        if (d == 0.0) {
            if (o < lo || o > hi) return std::nullopt;
            continue;
        }
        double t0 = (lo - o) / d, t1 = (hi - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar) return std::nullopt;
    return tNear;
}

// Sure when the box grown by the slack is missed, or the box shrunk by it (on its axes thicker
// than twice the slack, so flat leaf boxes stay flat) is hit.
BoxTest classify(const Bounds3f& box, const OracleRay& ray, double slack) {
    if (!entry(box, ray, slack)) return BoxTest::Miss;
    Bounds3f inner = box;
    for (int a = 0; a < 3; ++a)
        if (box.upper[a] - box.lower[a] > 2 * slack) {
            inner.lower[a] += float(slack);
            inner.upper[a] -= float(slack);
        }
    return entry(inner, ray, 0.0) ? BoxTest::Hit : BoxTest::Unsure;
}

struct FirstLeaf {
    bool sure = true;
    int leaf = -1;  // -1: the ray reaches no leaf
};

// The first leaf of a near-first walk whose box and every ancestor's box the ray hits.
void firstLeaf(const Bvh& bvh, uint32_t node, const OracleRay& ray, const std::array<bool, 3>& negative, double slack,
               FirstLeaf& out) {
    if (!out.sure || out.leaf >= 0) return;
    BoxTest test = classify(bvh.nodes[node].bounds, ray, slack);
    if (test == BoxTest::Unsure) out.sure = false;
    if (test != BoxTest::Hit) return;
    const BvhNode& n = bvh.nodes[node];
    if (n.isLeaf()) {
        out.leaf = int(node);
        return;
    }
    uint32_t first = node + 1, second = n.offset;
    bool secondFirst = negative[n.axis];
    firstLeaf(bvh, secondFirst ? second : first, ray, negative, slack, out);
    firstLeaf(bvh, secondFirst ? first : second, ray, negative, slack, out);
}

}  // namespace

VisitOrderVerdict judgeVisitOrder(const Bvh& bvh, const Scene& scene, const std::vector<Ray>& rays,
                                  const std::vector<std::vector<uint32_t>>& tested) {
    VisitOrderVerdict verdict;
    if (bvh.nodes.empty()) return verdict;
    std::vector<int> leafOf(scene.primitiveCount(), -1);
    for (uint32_t i = 0; i < bvh.nodes.size(); ++i)
        if (bvh.nodes[i].isLeaf())
            for (uint32_t k = bvh.nodes[i].offset; k < bvh.nodes[i].offset + bvh.nodes[i].primCount; ++k) leafOf[bvh.primIndices[k]] = int(i);
    const Bounds3f& root = bvh.nodes[0].bounds;
    Vec3 extent = root.diagonal();
    double size = std::max({1.0, double(extent.x), double(extent.y), double(extent.z)});
    Oracle oracle(scene);
    auto problem = [&](size_t r, const std::string& what) {
        ++verdict.wrong;
        if (verdict.problems.size() >= 5) return;
        verdict.problems.push_back(describeRay(rays[r]) + ": " + what);
        verdict.wrongRays.push_back(r);
    };
    for (size_t r = 0; r < rays.size(); ++r) {
        OracleRay ray = OracleRay::from(rays[r]);
        std::array<bool, 3> negative{std::signbit(rays[r].direction.x), std::signbit(rays[r].direction.y), std::signbit(rays[r].direction.z)};
        FirstLeaf expected;
        firstLeaf(bvh, 0, ray, negative, kBoxEdgeSlack * size, expected);
        if (!expected.sure) continue;
        ++verdict.graded;
        const std::vector<uint32_t>& prims = tested[r];
        int got = prims.empty() ? -1 : leafOf[prims.front()];
        if (got != expected.leaf) {
            problem(r, expected.leaf < 0 ? "tested primitives although the ray reaches no leaf"
                             : got < 0         ? "tested no primitive; the first leaf of a near-first walk is node " + std::to_string(expected.leaf)
                                               : "entered node " + std::to_string(got) + " first; a near-first walk enters node " +
                                                     std::to_string(expected.leaf) + " first (is the near child the right one?)");
            continue;
        }
        // Every later leaf: entered no farther than the closest hit among what came before it.
        double best = ray.tMax;
        int current = got;
        for (uint32_t prim : prims) {
            if (leafOf[prim] != current) {
                current = leafOf[prim];
                std::optional<double> enter = current < 0 ? std::nullopt : entry(bvh.nodes[current].bounds, ray, 0.0);
                if (enter && *enter > best + kDistanceSlack * std::max({1.0, best, size})) {
                    char text[160];
                    std::snprintf(text, sizeof text, "entered node %d at t = %.9g, beyond the closest hit so far at t = %.9g (is tMax shrunk?)",
                                  current, *enter, best);
                    problem(r, text);
                    break;
                }
            }
            // A hit this close to an edge may be a miss in float: it does not count as found.
            if (std::optional<OracleHit> hit = oracle.intersect(prim, ray); hit && hit->edgeMargin >= kHitEdgeMargin)
                best = std::min(best, hit->t);
        }
    }
    return verdict;
}

}  // namespace rtlab::grader
