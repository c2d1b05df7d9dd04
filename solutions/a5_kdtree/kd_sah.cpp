// Reference solution: the SAH cost of a KD-tree plane (docs/a5-kdtree.md#the-cost-of-a-plane).
#include "framework/interface/a5_kdtree.h"

#include <limits>

namespace rtlab {

namespace {

// In double from the float corners: a float area of a large box overflows (or loses the small
// halves to rounding) long before its coordinates do.
double surfaceArea(const Bounds3f& box) {
    double dx = double(box.upper.x) - box.lower.x, dy = double(box.upper.y) - box.lower.y, dz = double(box.upper.z) - box.lower.z;
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

}  // namespace

double kdSahCost(const Bounds3f& node, int axis, float position, uint32_t nBelow, uint32_t nAbove, const KdCosts& costs) {
    double area = surfaceArea(node);
    // A point or a segment: no ray can be expected to pass either half, and 0/0 would be NaN.
    if (!(area > 0.0)) return std::numeric_limits<double>::infinity();
    Bounds3f below = node, above = node;
    below.upper[axis] = position;
    above.lower[axis] = position;
    // Cutting off empty space is worth more than its area says: a ray that enters the empty half
    // tests nothing there.
    double bonus = (nBelow == 0 || nAbove == 0) ? costs.emptyBonus : 0.0;
    return costs.traversal +
           costs.intersection * (1.0 - bonus) * (surfaceArea(below) / area * nBelow + surfaceArea(above) / area * nAbove);
}

}  // namespace rtlab
