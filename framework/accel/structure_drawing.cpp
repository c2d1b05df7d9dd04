#include "framework/accel/structure_drawing.h"


#include <cmath>

namespace rtlab {
namespace {

// The half-space dot(normal, x) >= offset (side +1) or <= offset (side -1).
struct HalfSpace {
    DVec3 normal;
    double offset;
};

// Sutherland-Hodgman: the part of a convex polygon inside one half-space.
std::vector<DVec3> clip(const std::vector<DVec3>& polygon, const HalfSpace& h) {
    std::vector<DVec3> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const DVec3& a = polygon[i];
        const DVec3& b = polygon[(i + 1) % polygon.size()];
        double da = glm::dot(h.normal, a) - h.offset, db = glm::dot(h.normal, b) - h.offset;
        if (da >= 0.0) out.push_back(a);
        // Strictly on opposite sides: a corner on the plane is kept once, as itself.
        if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// The plane inside box and every half-space: a square on the plane larger than the box, clipped.
std::vector<Vec3> planeInCell(const StructurePlane& plane, const Bounds3f& box, const std::vector<HalfSpace>& sides) {
    DVec3 lower(box.lower), upper(box.upper);
    DVec3 n = glm::normalize(plane.normal);
    double offset = plane.offset / glm::length(plane.normal);
    DVec3 centre = 0.5 * (lower + upper);
    centre -= n * (glm::dot(n, centre) - offset);
    DVec3 helper = std::abs(n.x) < 0.9 ? DVec3(1, 0, 0) : DVec3(0, 1, 0);
    DVec3 u = glm::normalize(glm::cross(n, helper)), v = glm::cross(n, u);
    double r = glm::length(upper - lower) + 1.0;
    std::vector<DVec3> polygon = {centre + r * (u + v), centre + r * (v - u), centre - r * (u + v), centre + r * (u - v)};
    for (int a = 0; a < 3 && !polygon.empty(); ++a) {
        DVec3 axis(0.0);
        axis[a] = 1.0;
        polygon = clip(clip(polygon, {axis, lower[a]}), {-axis, -upper[a]});
    }
    for (const HalfSpace& h : sides)
        if (!polygon.empty()) polygon = clip(polygon, h);
    std::vector<Vec3> out;
    for (const DVec3& p : polygon) out.emplace_back(p);
    return out;
}

}  // namespace

StructureDrawing drawLevels(const StructureView&, const NodeMask&) { return StructureDrawing{}; }

StructureDrawing drawCells(const StructureView&, const NodeMask&) {
    StructureDrawing drawing;
    drawing.style = DrawingStyle::Cells;
    return drawing;
}

StructureDrawing drawPlanes(const StructureView& view, const NodeMask& drawn) {
    StructureDrawing drawing;
    drawing.style = DrawingStyle::Planes;
    if (view.nodes.empty() || view.planes.size() != view.nodes.size()) return drawing;
    // Depth first with the half-spaces of the ancestors; an explicit stack, since a BSP of a
    // hostile scene may be deep. A node reached twice (a malformed view) is drawn once.
    std::vector<bool> seen(view.nodes.size(), false);
    struct Pending {
        uint32_t node;
        std::vector<HalfSpace> sides;
    };
    std::vector<Pending> stack = {{0, {}}};
    while (!stack.empty()) {
        Pending p = std::move(stack.back());
        stack.pop_back();
        if (p.node >= view.nodes.size() || seen[p.node] || (!drawn.empty() && (p.node >= drawn.size() || !drawn[p.node]))) continue;
        seen[p.node] = true;
        const StructureNode& node = view.nodes[p.node];
        const StructurePlane& plane = view.planes[p.node];
        if (node.childCount == 0 || !plane.exists()) continue;
        std::vector<Vec3> polygon = planeInCell(plane, node.bounds, p.sides);
        if (polygon.size() >= 3) drawing.planes.push_back({p.node, std::move(polygon)});
        if (node.childCount != 2 || size_t(node.firstChild) + 2 > view.children.size()) continue;
        // Children {back or below, front or above}: the back side is dot(n, x) <= offset.
        std::vector<HalfSpace> back = p.sides, front = p.sides;
        back.push_back({-plane.normal, -plane.offset});
        front.push_back({plane.normal, plane.offset});
        stack.push_back({view.children[node.firstChild + 1], std::move(front)});
        stack.push_back({view.children[node.firstChild], std::move(back)});
    }
    return drawing;
}

std::vector<float> sahShares(const StructureView& view) {
    std::vector<float> shares(view.nodes.size(), 0.0f);
    double total = sahCost(view);
    if (view.nodes.empty() || total <= 0.0) return shares;
    double rootArea = view.nodes[0].bounds.surfaceArea();
    if (rootArea <= 0.0) return shares;
    for (size_t i = 0; i < view.nodes.size(); ++i) {
        const StructureNode& n = view.nodes[i];
        double area = n.bounds.surfaceArea() / rootArea;
        shares[i] = static_cast<float>((n.childCount > 0 ? area : n.primCount * area) / total);
    }
    return shares;
}

}  // namespace rtlab
