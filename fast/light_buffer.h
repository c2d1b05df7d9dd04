// A light buffer (docs/performance.md, "The renderer"): shadow rays toward one point light,
// answered by the few triangles that can block them instead of a walk through the BVH.
//
// Seen from the light, the scene's bounds lie in a cone. A grid on a plane across it (a camera
// at the light, looking at the bounds) lists in each cell the triangles whose projection,
// widened by a rounding margin, covers the cell, nearest to the light first. A shadow ray from
// o toward the light can only be blocked by a triangle listed in the cell o projects to, and
// only by one no farther from the light than o: those are tested with the packets' exact test
// (triangle_packet.h), nearest first, and the answer is the BVH's, bit for bit. For a lit point
// that is the handful of triangles around it; the BVH walks every node between it and the light.
//
// The margin. The ray's direction is light - o rounded, off by at most u |light - o| (u = 2^-24);
// a point it hits at distance r from the light is therefore seen from the light within about
// u |light - o| / r of o's direction, and the exact test's own rounding moves the hit by a few
// u times the scene's reach more. A triangle whose nearest point is r_T from the light is
// widened by 64 u reach / r_T, several times both together, and every triangle nearer to the
// light than 1/1000 of the reach makes the buffer decline.
#pragma once

#include "fast/triangle_packet.h"
#include "framework/accel/accelerator.h"

#include <memory>
#include <vector>

namespace rtlab {

class LightBuffer final : public PointOccluder {
public:
    // nullptr where it cannot help or could not be sure: spheres among the primitives, the
    // light inside or beside the triangles' bounds (they must lie in a cone of half-angle under
    // 78 degrees around it), a triangle nearer to the light than 1/1000 of the bounds' far
    // corner. Rays it was not made for go to fallback, which must outlive it.
    static std::unique_ptr<LightBuffer> make(const PrimitiveSet& primitives, const Vec3& light, const Accelerator& fallback);

    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    size_t memoryBytes() const;

private:
    LightBuffer(const Vec3& light, const Accelerator& fallback) : light_(light), fallback_(fallback) {}

    // The plane coordinates of p, or false when p is not in front of the light.
    bool project(const DVec3& p, double& x, double& y) const;
    // The cell, along one side, of plane coordinate value (clamped to the grid).
    int cellOf(double value, double gridStart, int cells) const;

    Vec3 light_;
    const Accelerator& fallback_;
    DVec3 axis_{0.0}, u_{0.0}, v_{0.0};  // the plane's normal (toward the bounds) and its axes
    double gridX_ = 0.0, gridY_ = 0.0, cellSize_ = 1.0;  // the grid's corner and its cells' side
    int columns_ = 0, rows_ = 0;
    double slack_ = 0.0;  // how much nearer than a triangle a hit on it may seem: 64 u reach
    std::vector<uint32_t> cellStart_;   // each cell's first packet; one more at the end
    std::vector<TrianglePacket> packets_;
    std::vector<float> packetReach_;    // the nearest distance to the light of a packet's triangles
};

}  // namespace rtlab
