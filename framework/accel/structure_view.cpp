#include "framework/accel/structure_view.h"

namespace rtlab {

double sahCost(const StructureView& view, double traversalCost, double intersectionCost) {
    if (view.nodes.empty()) return 0.0;
    double rootArea = view.nodes[0].bounds.surfaceArea();
    if (rootArea <= 0.0) return intersectionCost * view.primIndices.size();
    double cost = 0.0;
    for (const StructureNode& n : view.nodes) {
        double area = n.bounds.surfaceArea() / rootArea;
        cost += n.childCount > 0 ? traversalCost * area : intersectionCost * n.primCount * area;
    }
    return cost;
}

}  // namespace rtlab
