// Assignment a5, part 1: the cost of a plane.      Guide: docs/a5-kdtree.md#the-cost-of-a-plane
//
// Contract (framework/interface/a5_kdtree.h):
//   kdSahCost = K_T + K_I (1 - eb) (SA_below / SA * nBelow + SA_above / SA * nAbove)
//   * SA: the node's surface area; SA_below, SA_above: the node's with upper[axis] = position,
//     and with lower[axis] = position. In double: dx = double(upper.x) - lower.x, ...,
//     SA = 2 (dx dy + dy dz + dz dx).
//   * K_T = costs.traversal, K_I = costs.intersection; eb = costs.emptyBonus when nBelow == 0 or
//     nAbove == 0, otherwise 0.
//   * A node with SA == 0 (a point or a segment) costs +infinity.
//
// Hints:
//   * A flat node (zero width on one axis) still has an area: two faces.
//   * Bounds3f::surfaceArea() works in float; a box of side 2^62 overflows it.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

double kdSahCost(const Bounds3f& node, int axis, float position, uint32_t nBelow, uint32_t nAbove, const KdCosts& costs) {
    (void)node, (void)axis, (void)position, (void)nBelow, (void)nAbove, (void)costs;
    throw NotImplemented("a5 kdSahCost (assignments/a5_kdtree/kd_sah.cpp)");
}

}  // namespace rtlab
