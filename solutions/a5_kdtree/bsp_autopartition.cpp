// Reference solution beyond the lecture: a BSP tree whose planes come from the triangles
// themselves (an autopartition, docs/bsp.md#rtlabs-autopartition), and its front-to-back
// traversal: the KD-tree's walk with tSplit = (offset - n.o) / (n.d).
#include "framework/interface/a5_kdtree.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

namespace {

struct Plane {
    DVec3 normal;
    double offset;
};

enum class Side { In, Front, Back, Both };

// The plane of a triangle, in double from its float vertices; false for a degenerate one.
bool planeOf(const std::array<Vec3, 3>& v, Plane* plane) {
    DVec3 p0(v[0]), n = glm::cross(DVec3(v[1]) - p0, DVec3(v[2]) - p0);
    double length = glm::length(n);
    if (!(length > 0.0)) return false;
    plane->normal = n / length;
    plane->offset = glm::dot(plane->normal, p0);
    return true;
}

class Builder {
public:
    Builder(std::span<const std::array<Vec3, 3>> triangles, std::span<const Bounds3f> primBounds, const BspOptions& options, BspTree& tree)
        : triangles_(triangles), primBounds_(primBounds), options_(options), tree_(tree) {}

    void build(const std::vector<uint32_t>& prims, int depth) {
        Plane plane;
        if (prims.size() <= options_.maxPrims || depth >= options_.maxDepth || !choosePlane(prims, &plane)) {
            addNode(Plane{}, prims, true);
            return;
        }
        std::vector<uint32_t> in, front, back;
        for (uint32_t prim : prims) {
            Side side = sideOf(prim, plane);
            if (side == Side::In) in.push_back(prim);
            if (side == Side::Front || side == Side::Both) front.push_back(prim);
            if (side == Side::Back || side == Side::Both) back.push_back(prim);
        }
        size_t node = addNode(plane, in, false);
        build(back, depth + 1);
        tree_.nodes[node].front = static_cast<uint32_t>(tree_.nodes.size());
        build(front, depth + 1);
    }

private:
    // Where a primitive lies: its vertices (a sphere: its box's corners) against the plane,
    // with the band of half width thickness counted as the plane itself.
    Side sideOf(uint32_t prim, const Plane& plane) const {
        double lowest = INFINITY, highest = -INFINITY;
        auto take = [&](const Vec3& p) {
            double s = glm::dot(plane.normal, DVec3(p)) - plane.offset;
            lowest = std::min(lowest, s);
            highest = std::max(highest, s);
        };
        if (prim < triangles_.size()) {
            for (const Vec3& v : triangles_[prim]) take(v);
        } else {
            const Bounds3f& b = primBounds_[prim];
            for (int corner = 0; corner < 8; ++corner) take(Vec3(b[corner & 1].x, b[corner >> 1 & 1].y, b[corner >> 2].z));
        }
        double t = tree_.thickness;
        if (lowest >= -t && highest <= t) return Side::In;
        if (lowest >= -t) return Side::Front;
        if (highest <= t) return Side::Back;
        return Side::Both;
    }

    // Of kBspCandidates triangles spread evenly over the node's list, the plane with the lowest
    // kBspCutWeight * cuts + |front - back|; false when there is none, or when it cuts more
    // than half of the primitives.
    bool choosePlane(const std::vector<uint32_t>& prims, Plane* best) const {
        size_t bestScore = 0, bestCuts = 0;
        bool found = false;
        for (size_t k = 0; k < size_t(kBspCandidates) && k < prims.size(); ++k) {
            // Spread out, not the first few: neighbours in a mesh's list lie side by side on its
            // surface, and their planes all leave the rest of a closed surface on one side.
            uint32_t candidate = prims[k * prims.size() / std::min<size_t>(kBspCandidates, prims.size())];
            Plane plane;
            if (candidate >= triangles_.size() || !planeOf(triangles_[candidate], &plane)) continue;
            size_t cuts = 0, front = 0, back = 0;
            for (uint32_t prim : prims) {
                Side side = sideOf(prim, plane);
                cuts += side == Side::Both;
                front += side == Side::Front;
                back += side == Side::Back;
            }
            size_t score = kBspCutWeight * cuts + (front > back ? front - back : back - front);
            if (!found || score < bestScore) {
                *best = plane;
                bestScore = score;
                bestCuts = cuts;
                found = true;
            }
        }
        // A plane that copies most primitives into both children makes the tree grow faster
        // than it sorts anything.
        return found && 2 * bestCuts <= prims.size();
    }

    size_t addNode(const Plane& plane, const std::vector<uint32_t>& prims, bool leaf) {
        BspNode node;
        node.normal = plane.normal;
        node.offset = plane.offset;
        node.firstPrim = static_cast<uint32_t>(tree_.primIndices.size());
        node.primCount = static_cast<uint32_t>(prims.size());
        node.leaf = leaf;
        tree_.primIndices.insert(tree_.primIndices.end(), prims.begin(), prims.end());
        tree_.nodes.push_back(node);
        return tree_.nodes.size() - 1;
    }

    std::span<const std::array<Vec3, 3>> triangles_;
    std::span<const Bounds3f> primBounds_;
    const BspOptions& options_;
    BspTree& tree_;
};

struct Pending {
    uint32_t node;
    float tMin, tMax;
};

// Walks the tree's cells the segment crosses, near to far, calling visit(node) on every node
// (its own primitives) until it returns true; with closestHit, stops once the rest lies beyond.
template <typename Visit>
void walk(const BspTree& tree, Traversal& traversal, float tMin, float tMax, const float* closestHit, Visit&& visit) {
    std::array<Pending, kBspMaxDepthLimit + 1> stack;
    int pending = 0;
    uint32_t index = 0;
    const Ray& ray = traversal.ray();
    for (;;) {
        const BspNode& node = tree.nodes[index];
        if (visit(node)) return;
        if (!node.leaf) {
            traversal.countPlaneStep();
            // Along the ray the signed distance is a + b t: the ray is on the front side (or in
            // the band) where a + b t >= -thickness, on the back side where a + b t <= thickness.
            double a = glm::dot(node.normal, DVec3(ray.origin)) - node.offset, b = glm::dot(node.normal, DVec3(ray.direction));
            double lo = tMin, hi = tMax, th = tree.thickness;
            double frontFrom = lo, frontTo = hi, backFrom = lo, backTo = hi;
            if (b > 0.0) {
                frontFrom = std::max(lo, (-th - a) / b);
                backTo = std::min(hi, (th - a) / b);
            } else if (b < 0.0) {
                frontTo = std::min(hi, (-th - a) / b);
                backFrom = std::max(lo, (th - a) / b);
            } else {
                if (a < -th) frontTo = -INFINITY;
                if (a > th) backTo = -INFINITY;
            }
            bool frontFirst = b < 0.0 || (b == 0.0 && a >= 0.0);
            Pending near{frontFirst ? node.front : index + 1, float(frontFirst ? frontFrom : backFrom), float(frontFirst ? frontTo : backTo)};
            Pending far{frontFirst ? index + 1 : node.front, float(frontFirst ? backFrom : frontFrom), float(frontFirst ? backTo : frontTo)};
            if (far.tMin <= far.tMax) stack[pending++] = far;
            if (near.tMin <= near.tMax) {
                index = near.node;
                tMin = near.tMin;
                tMax = near.tMax;
                continue;
            }
        }
        if (pending == 0) return;
        Pending next = stack[--pending];
        if (closestHit && *closestHit < next.tMin) return;
        index = next.node;
        tMin = next.tMin;
        tMax = next.tMax;
    }
}

std::span<const uint32_t> primitivesOf(const BspTree& tree, const BspNode& node) {
    return {tree.primIndices.data() + node.firstPrim, node.primCount};
}

}  // namespace

BspTree buildBspAutopartition(std::span<const std::array<Vec3, 3>> triangles, std::span<const Bounds3f> primBounds,
                              const BspOptions& options) {
    BspTree tree;
    std::vector<uint32_t> prims;
    for (uint32_t prim = 0; prim < primBounds.size(); ++prim)
        if (isPlaceable(primBounds[prim])) {
            prims.push_back(prim);
            tree.bounds.extend(primBounds[prim]);
        }
    if (prims.empty()) return tree;
    float scale = std::max({1.0f, std::abs(tree.bounds.lower.x), std::abs(tree.bounds.lower.y), std::abs(tree.bounds.lower.z),
                            std::abs(tree.bounds.upper.x), std::abs(tree.bounds.upper.y), std::abs(tree.bounds.upper.z)});
    tree.thickness = kBspRelativeThickness * scale;
    Builder(triangles, primBounds, options, tree).build(prims, 0);
    return tree;
}

bool intersectBsp(const BspTree& tree, Traversal& traversal, Hit& hit) {
    float tMin;
    if (tree.nodes.empty() || !traversal.hitsBox(tree.bounds, hit.t, &tMin)) return false;
    walk(tree, traversal, tMin, hit.t, &hit.t, [&](const BspNode& node) {
        for (uint32_t prim : primitivesOf(tree, node)) traversal.intersectOnce(prim, hit);
        return false;
    });
    return hit.found();
}

bool occludedBsp(const BspTree& tree, Traversal& traversal) {
    float tMin;
    if (tree.nodes.empty() || !traversal.hitsBox(tree.bounds, traversal.ray().tMax, &tMin)) return false;
    bool occluded = false;
    walk(tree, traversal, tMin, traversal.ray().tMax, nullptr, [&](const BspNode& node) {
        for (uint32_t prim : primitivesOf(tree, node))
            if (traversal.occludesOnce(prim)) return occluded = true;
        return false;
    });
    return occluded;
}

}  // namespace rtlab
