// The KD-tree of assignment a5 (docs/a5-kdtree.md): space cut by one axis-aligned plane per
// interior node, as pbrt lays it out. Interior nodes store the plane (axis and position) and their
// children; leaves store primitives. A primitive is listed in every leaf its box overlaps.
//
//  * nodes[0] is the root; nodes are in depth-first order, below child first: an interior
//    node's below child is the node right after it, its above child is aboveChild().
//  * A leaf covers primIndices[firstPrim() .. firstPrim() + primCount()), in increasing order.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/float_bits.h"

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace rtlab {

// The SAH of a KD-tree (docs/conventions.md#kd-trees), pbrt-v3's constants: one plane step
// costs K_T, one primitive test K_I, and a split with an empty side is forgiven the share eb of
// its primitive tests.
inline constexpr double kKdTraversalCost = 1.0;
inline constexpr double kKdIntersectionCost = 80.0;
inline constexpr double kKdEmptyBonus = 0.5;
// The deepest a KD-tree may be (maxDepth's upper limit), and so the size of a traversal stack:
// a ray keeps at most one pending child per level.
inline constexpr int kKdMaxDepthLimit = 64;
// Splits that cost more than the leaf they replace, allowed on one path before it must end.
inline constexpr int kKdMaxBadRefines = 3;
// The traversal's margin for rounding: a plane distance tSplit = (split - o) * invDirection and
// a segment end (an ancestor's tSplit, or the tree's exit) are each within gamma(3) of the true
// value, so two of them that are equal in exact arithmetic (a ray through the corner where two
// planes meet) compare within this factor.
inline constexpr float kKdRoundingMargin = 1.0f + 2.0f * gamma(3);

struct KdCosts {
    double traversal = kKdTraversalCost;        // K_T (0 .. 1000)
    double intersection = kKdIntersectionCost;  // K_I (0.001 .. 1000)
    double emptyBonus = kKdEmptyBonus;          // eb (0 .. 1)
};

struct KdTreeOptions {
    KdCosts costs;
    uint32_t maxPrims = 1;  // a node with at most this many primitives is a leaf (1 .. 65535)
    int maxDepth = 0;       // 0: kdMaxDepth(N); otherwise 1 .. kKdMaxDepthLimit
};

// --- Events: where primitive boxes begin and end along one axis --------------------------------

// At equal positions: End < Planar < Start (Wald and Havran 2006).
enum class KdEventType : uint8_t { End = 0, Planar = 1, Start = 2 };

struct KdEvent {
    float position;
    KdEventType type;
    uint32_t prim;
    bool operator==(const KdEvent&) const = default;
};

// --- Splits ------------------------------------------------------------------------------------

// Which side of a plane a primitive goes to (kdClassify), and where primitives lying in the
// plane itself go (KdSplit::planarSide: Below or Above).
enum class KdSide : uint8_t { Below = 0, Above = 1, Both = 2 };

struct KdSplit {
    int axis = -1;  // -1: no candidate plane
    float position = 0.0f;
    KdSide planarSide = KdSide::Below;
    double cost = std::numeric_limits<double>::infinity();
    uint32_t nBelow = 0, nAbove = 0;

    bool found() const { return axis >= 0; }
};

// What the leaf rule decided for a node, and the bad refines its children inherit.
struct KdNodeDecision {
    bool leaf;
    int badRefines;
};

// --- The tree ----------------------------------------------------------------------------------

// 8 bytes: a plane (axis, position, above child) or a leaf (first primitive, count).
class KdNode {
public:
    KdNode() = default;
    static KdNode interior(int axis, float split, uint32_t aboveChild) {
        return KdNode(std::bit_cast<uint32_t>(split), uint32_t(axis) | aboveChild << 2);
    }
    static KdNode leaf(uint32_t firstPrim, uint32_t primCount) { return KdNode(firstPrim, kLeafFlag | primCount << 2); }

    bool isLeaf() const { return (bits_ & 3) == kLeafFlag; }
    int axis() const { return int(bits_ & 3); }                           // interior: 0 = x, 1 = y, 2 = z
    float split() const { return std::bit_cast<float>(value_); }          // interior: the plane's position
    uint32_t aboveChild() const { return bits_ >> 2; }                    // interior
    uint32_t firstPrim() const { return value_; }                         // leaf: into KdTree::primIndices
    uint32_t primCount() const { return bits_ >> 2; }                     // leaf

    // Bit-exact equality: the same plane or the same leaf.
    bool operator==(const KdNode&) const = default;

private:
    static constexpr uint32_t kLeafFlag = 3;
    KdNode(uint32_t value, uint32_t bits) : value_(value), bits_(bits) {}
    uint32_t value_ = 0;  // interior: the split position's bits; leaf: the first primitive
    uint32_t bits_ = 0;   // low 2 bits: axis, or 3 for a leaf; the rest: above child or count
};
static_assert(sizeof(KdNode) == 8, "a KD-tree node is two words, as in pbrt");

// The most a child index or a leaf's count can be (30 bits).
inline constexpr uint32_t kKdMaxIndex = (1u << 30) - 1;

struct KdTree {
    Bounds3f bounds;                    // the root's box: the union of the placeable primitives' boxes
    std::vector<KdNode> nodes;          // empty when no primitive is placeable
    std::vector<uint32_t> primIndices;  // the leaves' lists, one after the other
    int maxDepth = 0;                   // the depth limit the build used
};

// Where a ray's segment [tMin, tMax] goes at an interior node (kdChildOrder).
struct KdChildOrder {
    bool belowFirst;   // the below child is the near one
    bool visitFirst;   // the near child is entered
    bool visitSecond;  // the far child is entered
    float tSplit;      // where the ray meets the plane
};

}  // namespace rtlab
