// The scene seen from one point (docs/performance.md, "The renderer"): rays that start at the
// point (a camera's) or end at it (shadow rays toward a point light), answered by the few
// triangles in their direction instead of a walk through the BVH. POV-Ray 3.6 had both, as the
// vista buffer and the light buffer; 3.7 dropped them.
//
// Seen from the point, the scene's bounds lie in a cone. A grid on a plane across it (a camera
// at the point, looking at the bounds) lists in each cell the triangles whose projection,
// widened by a rounding margin, covers the cell, nearest to the point first, four to a packet.
//  * A ray from the point can only hit triangles listed in the cell of its direction. They are
//    tested in that order with the packets' exact test (triangle_packet.h), until the next
//    packet's nearest triangle lies beyond the nearest hit so far.
//  * A shadow ray from o toward the point can only be blocked by a triangle listed in the cell
//    o projects to, and only by one no farther from the point than o.
// The answers are the BVH's: the same hits (of equally near triangles hit by one ray, perhaps
// another one) and the same blocked rays.
//
// The margin. A shadow ray's direction is point - o rounded, off by at most u |point - o|
// (u = 2^-24); a point it hits at distance r from the light is therefore seen from the light
// within about u |point - o| / r of o's direction, and the exact test's own rounding moves a hit
// by a few u times the scene's reach more (a ray from the point has only the latter). A
// triangle whose nearest point is r_T away is widened by 64 u reach / r_T, several times both
// together, and a triangle nearer than 1/1000 of the reach makes the view decline.
#pragma once

#include "fast/triangle_packet.h"
#include "framework/accel/accelerator.h"

#include <memory>
#include <vector>

namespace rtlab {

class PointView final : public PointQueries {
public:
    // nullptr where it cannot help or could not be sure: spheres among the primitives, the
    // point inside or beside the triangles' bounds (they must lie in a cone of half-angle under
    // 78 degrees around it), or a triangle nearer to it than 1/1000 of the bounds' far corner.
    // Rays it was not made for go to fallback, which must outlive it.
    static std::unique_ptr<PointView> make(const PrimitiveSet& primitives, const Vec3& point, const Accelerator& fallback);

    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;

private:
    PointView(const Vec3& point, const Accelerator& fallback) : point_(point), fallback_(fallback) {}

    // A triangle's rectangle on the plane, widened by its margin, and its nearest distance to
    // the point.
    struct Rect {
        double x0, y0, x1, y1, reach;
    };

    // The building steps. frameBounds sets the plane across the cone the bounds lie in, seen
    // from the point, and gives the cone's least cosine and the farthest corner's distance;
    // false when the bounds do not lie within 78 degrees of its axis. rectangles gives every
    // triangle's Rect; false when one is too near the point. sizeGrid lays the cells over the
    // rectangles, fillCells lists each cell's triangles.
    bool frameBounds(const Bounds3f& bounds, double& minCosine, double& reach);
    bool rectangles(const PrimitiveSet& primitives, double planeScale, double reach, std::vector<Rect>& rects) const;
    void sizeGrid(const std::vector<Rect>& rects);
    void fillCells(const PrimitiveSet& primitives, const std::vector<Rect>& rects);
    // How many columns and rows of cells a rectangle covers.
    int columnsOf(const Rect& rect) const;
    int rowsOf(const Rect& rect) const;

    // The plane coordinates of the direction w from the point, or false when w does not point
    // into the cone's side of the plane.
    bool project(const DVec3& w, double& x, double& y) const;
    // The cell of plane coordinates (x, y), or -1 outside the grid.
    long cellAt(double x, double y) const;
    // The cell, along one side, of plane coordinate value (clamped to the grid).
    int cellOf(double value, double gridStart, int cells) const;

    Vec3 point_;
    const Accelerator& fallback_;
    DVec3 axis_{0.0}, u_{0.0}, v_{0.0};  // the plane's normal (toward the bounds) and its axes
    double gridX_ = 0.0, gridY_ = 0.0, cellSize_ = 1.0;  // the grid's corner and its cells' side
    double inverseCellSize_ = 1.0;
    int columns_ = 0, rows_ = 0;
    double slack_ = 0.0;  // how much nearer than a triangle a hit on it may seem: 64 u reach
    std::vector<uint32_t> cellStart_;   // each cell's first packet; one more at the end
    std::vector<TrianglePacket> packets_;
    std::vector<float> packetReach_;    // the nearest distance to the point of a packet's triangles
};

}  // namespace rtlab
