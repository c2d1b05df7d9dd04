// A read-only, accelerator-neutral view of a built structure, so the grader can check
// invariants and recompute SAH cost without trusting the accelerator: nodes with bounds, their
// children and the primitives of leaves; for trees that cut space by planes (KD-tree, BSP),
// each interior node's plane, which the viewer draws.
#pragma once

#include "framework/core/bounds.h"

#include <cstdint>
#include <vector>

namespace rtlab {

struct StructureNode {
    Bounds3f bounds;
    uint32_t firstChild = 0;  // into StructureView::children
    uint32_t childCount = 0;  // 0 for a leaf
    uint32_t firstPrim = 0;   // into StructureView::primIndices
    uint32_t primCount = 0;
};

// The plane dot(normal, x) = offset; a zero normal for a node that has none.
struct StructurePlane {
    DVec3 normal{0.0};
    double offset = 0.0;

    bool exists() const { return normal != DVec3(0.0); }
};

struct StructureView {
    std::vector<StructureNode> nodes;   // nodes[0] is the root
    std::vector<uint32_t> children;     // node indices
    std::vector<uint32_t> primIndices;  // primitive ids referenced by leaves
    // Empty, or one per node: the plane an interior node splits its space by. A BSP node's
    // children are {back, front}: front is dot(normal, x) > offset; a KD-tree's {below, above}.
    std::vector<StructurePlane> planes;
};

// SAH cost of a tree (docs/a2-sah.md): sum over interior nodes of C_trav * S(n)/S(root) plus
// sum over leaves of N * C_isect * S(leaf)/S(root), with C_trav = C_isect = 1.
double sahCost(const StructureView& view, double traversalCost = 1.0, double intersectionCost = 1.0);

}  // namespace rtlab
