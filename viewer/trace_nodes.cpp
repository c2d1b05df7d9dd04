#include "viewer/trace_nodes.h"

#include "framework/core/fnv1a.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <tuple>
#include <unordered_map>

namespace rtlab::viewer {
namespace {

uint64_t boundsKey(const Bounds3f& b) {
    float v[6] = {b.lower.x, b.lower.y, b.lower.z, b.upper.x, b.upper.y, b.upper.z};
    return fnv1a64(v, sizeof v);
}

bool sameBits(const Bounds3f& a, const Bounds3f& b) {
    return std::memcmp(&a, &b, sizeof(Bounds3f)) == 0;
}

uint64_t listKey(const uint32_t* prims, size_t count) { return fnv1a64(prims, count * sizeof(uint32_t)); }

// Where the ray enters box (slab test in double), or +inf when it misses it.
double entryDistance(const Bounds3f& box, const Ray& ray) {
    double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        double o = ray.origin[a], d = ray.direction[a];
        if (d == 0.0) {
            if (o < box.lower[a] || o > box.upper[a]) return std::numeric_limits<double>::infinity();
            continue;
        }
        double ta = (box.lower[a] - o) / d, tb = (box.upper[a] - o) / d;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    return t0 <= t1 * (1.0 + 1e-6) + 1e-9 ? t0 : std::numeric_limits<double>::infinity();
}

bool isPrimitiveOp(TraceOpKind kind) { return kind == TraceOpKind::PrimitiveTest || kind == TraceOpKind::MailboxRepeat; }

bool isGrid(const StructureView& view, const std::array<int, 3>& resolution) {
    size_t cells = size_t(resolution[0]) * resolution[1] * resolution[2];
    return !view.nodes.empty() && view.nodes[0].childCount == cells && view.nodes.size() == cells + 1 &&
           size_t(view.nodes[0].firstChild) + cells <= view.children.size();
}

}  // namespace

std::vector<uint32_t> resolveTraceNodes(const StructureView& view, const TraversalTrace& trace, const Ray& ray,
                                        const std::vector<GridCell>& cells, const std::array<int, 3>& resolution) {
    std::vector<uint32_t> nodes(trace.ops.size(), kUnresolved);
    const size_t n = view.nodes.size();
    // Parents, to tell apart nodes with the same bounds (a BVH child as large as its parent): a
    // walk tests a node after its parent and once.
    std::vector<uint32_t> parentOf(n, kUnresolved);
    for (uint32_t i = 0; i < n; ++i) {
        const StructureNode& node = view.nodes[i];
        for (uint64_t c = node.firstChild; c < uint64_t(node.firstChild) + node.childCount && c < view.children.size(); ++c)
            if (view.children[c] < n && parentOf[view.children[c]] == kUnresolved && view.children[c] != 0) parentOf[view.children[c]] = i;
    }
    std::vector<bool> met(n, false);
    // Where a box test's node is looked for: first among the root and the children of the nodes
    // met so far (what a walk can test next), then, for a walk that jumps, among all nodes by
    // their bounds (built on the first such miss: a million-node tree costs its time once).
    std::vector<uint32_t> frontier;
    if (n > 0) frontier.push_back(0);
    std::unordered_multimap<uint64_t, uint32_t> byBounds;
    bool byBoundsBuilt = false;
    // Where a run of primitive tests' node is looked for: the nodes the ray's line passes through
    // (found from the root down), then all nodes, each by its list.
    std::unordered_multimap<uint64_t, uint32_t> alongRay, byList;
    bool alongRayBuilt = false, byListBuilt = false;
    auto addByList = [&](std::unordered_multimap<uint64_t, uint32_t>& map, uint32_t i) {
        const StructureNode& node = view.nodes[i];
        if (node.primCount == 0 || uint64_t(node.firstPrim) + node.primCount > view.primIndices.size()) return;
        map.emplace(listKey(view.primIndices.data() + node.firstPrim, node.primCount), i);
    };
    auto buildAlongRay = [&] {
        alongRayBuilt = true;
        std::vector<uint32_t> stack;
        std::vector<bool> seen(n, false);
        if (n > 0) stack.push_back(0);
        while (!stack.empty()) {
            uint32_t v = stack.back();
            stack.pop_back();
            if (seen[v]) continue;
            seen[v] = true;
            const StructureNode& node = view.nodes[v];
            if (entryDistance(node.bounds, ray) == std::numeric_limits<double>::infinity()) continue;
            addByList(alongRay, v);
            for (uint64_t c = node.firstChild; c < uint64_t(node.firstChild) + node.childCount && c < view.children.size(); ++c)
                if (view.children[c] < n) stack.push_back(view.children[c]);
        }
    };
    auto isCandidate = [&](uint32_t v, const std::vector<uint32_t>& run) {
        const StructureNode& node = view.nodes[v];
        return node.primCount == run.size() && uint64_t(node.firstPrim) + node.primCount <= view.primIndices.size() &&
               std::equal(run.begin(), run.end(), view.primIndices.begin() + node.firstPrim);
    };

    bool grid = isGrid(view, resolution);
    size_t cellStep = 0;
    double lastEntry = -std::numeric_limits<double>::infinity();
    std::vector<uint32_t> run;
    for (size_t i = 0; i < trace.ops.size(); ++i) {
        const TraceOp& op = trace.ops[i];
        switch (op.kind) {
        case TraceOpKind::BoxTest: {
            if (op.index >= trace.boxes.size()) break;
            const Bounds3f& box = trace.boxes[op.index];
            // Of the nodes with these bounds: the first one not met yet whose parent was, else the
            // first not met yet, else the first.
            uint32_t best[3] = {kUnresolved, kUnresolved, kUnresolved};
            auto consider = [&](uint32_t v) {
                if (!sameBits(view.nodes[v].bounds, box)) return;
                bool parentMet = v == 0 || (parentOf[v] != kUnresolved && met[parentOf[v]]);
                if (!met[v] && parentMet) best[0] = std::min(best[0], v);
                if (!met[v]) best[1] = std::min(best[1], v);
                best[2] = std::min(best[2], v);
            };
            for (uint32_t v : frontier) consider(v);
            if (best[0] == kUnresolved) {
                if (!byBoundsBuilt) {
                    for (uint32_t v = 0; v < n; ++v) byBounds.emplace(boundsKey(view.nodes[v].bounds), v);
                    byBoundsBuilt = true;
                }
                auto [from, to] = byBounds.equal_range(boundsKey(box));
                for (auto it = from; it != to; ++it) consider(it->second);
            }
            nodes[i] = best[0] != kUnresolved ? best[0] : best[1] != kUnresolved ? best[1] : best[2];
            if (nodes[i] != kUnresolved && !met[nodes[i]]) {
                met[nodes[i]] = true;
                const StructureNode& node = view.nodes[nodes[i]];
                for (uint64_t c = node.firstChild; c < uint64_t(node.firstChild) + node.childCount && c < view.children.size(); ++c)
                    if (view.children[c] < n) frontier.push_back(view.children[c]);
            }
            break;
        }
        case TraceOpKind::LeafEntry:
            if (op.index < n) nodes[i] = op.index;
            break;
        case TraceOpKind::CellStep: {
            size_t k = cellStep++;
            if (!grid || k >= cells.size()) break;
            const GridCell& c = cells[k];
            bool inside = true;
            for (int a = 0; a < 3; ++a) inside = inside && c[a] >= 0 && c[a] < resolution[a];
            if (!inside) break;
            size_t index = (size_t(c[2]) * resolution[1] + c[1]) * resolution[0] + c[0];
            nodes[i] = view.children[view.nodes[0].firstChild + index];
            break;
        }
        default:
            break;
        }
        // A run of primitive operations ends here: find the node whose list it is.
        bool endsRun = isPrimitiveOp(op.kind) && (i + 1 == trace.ops.size() || !isPrimitiveOp(trace.ops[i + 1].kind));
        if (isPrimitiveOp(op.kind)) run.push_back(op.index);
        if (!endsRun) continue;
        size_t first = i + 1 - run.size();
        // A leaf entry, a known cell step or a leaf's box test just before names the node itself.
        bool named = first > 0 && nodes[first - 1] != kUnresolved && !isPrimitiveOp(trace.ops[first - 1].kind) &&
                     view.nodes[nodes[first - 1]].childCount == 0;
        if (!named) {
            uint32_t best = kUnresolved;
            double bestEntry = std::numeric_limits<double>::infinity();
            uint64_t key = listKey(run.data(), run.size());
            if (!alongRayBuilt) buildAlongRay();
            auto [from, to] = alongRay.equal_range(key);
            if (from == to) {
                if (!byListBuilt) {
                    for (uint32_t v = 0; v < n; ++v) addByList(byList, v);
                    byListBuilt = true;
                }
                std::tie(from, to) = byList.equal_range(key);
            }
            for (auto it = from; it != to; ++it) {
                if (!isCandidate(it->second, run)) continue;
                double entry = entryDistance(view.nodes[it->second].bounds, ray);
                // Front to back: the nearest candidate not before the node resolved last.
                if (entry >= lastEntry - 1e-6 * std::abs(lastEntry) && (best == kUnresolved || entry < bestEntry)) {
                    best = it->second;
                    bestEntry = entry;
                }
            }
            if (best != kUnresolved) {
                for (size_t k = first; k <= i; ++k) nodes[k] = best;
                if (bestEntry < std::numeric_limits<double>::infinity()) lastEntry = bestEntry;
                // The plane steps just before a leaf: a front-to-back walk classifies the ray at
                // each node on its way down to the leaf, so they are its nearest ancestors.
                uint32_t ancestor = parentOf[best];
                for (size_t k = first; k-- > 0 && trace.ops[k].kind == TraceOpKind::PlaneStep && ancestor != kUnresolved;) {
                    nodes[k] = ancestor;
                    ancestor = parentOf[ancestor];
                }
            }
        } else {
            for (size_t k = first; k <= i; ++k) nodes[k] = nodes[first - 1];
        }
        run.clear();
    }
    return nodes;
}

int64_t firstDifference(const TraversalTrace& a, const TraversalTrace& b) {
    size_t common = std::min(a.ops.size(), b.ops.size());
    for (size_t i = 0; i < common; ++i) {
        const TraceOp& x = a.ops[i];
        const TraceOp& y = b.ops[i];
        bool same = x.kind == y.kind && x.hit == y.hit;
        if (same && x.kind == TraceOpKind::BoxTest)
            same = x.index < a.boxes.size() && y.index < b.boxes.size() && sameBits(a.boxes[x.index], b.boxes[y.index]);
        else if (same)
            same = x.index == y.index;
        if (!same) return static_cast<int64_t>(i);
    }
    return a.ops.size() == b.ops.size() ? -1 : static_cast<int64_t>(common);
}

}  // namespace rtlab::viewer
