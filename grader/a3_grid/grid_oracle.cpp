#include "grader/a3_grid/grid_oracle.h"

#include <algorithm>
#include <cmath>

namespace rtlab::grader {
namespace {

// Float rounding in a student's DDA moves a crossing by a few ulps per step; crossings closer
// than this (relative to the segment's scale) are not graded for their order.
constexpr double kAmbiguity = 1e-4;

}  // namespace

std::array<int, 3> expectedResolution(const Bounds3f& bounds, uint64_t primCount, const GridOptions& options) {
    Vec3 extent = bounds.diagonal();
    double longest = std::max({double(extent.x), double(extent.y), double(extent.z)});
    if (primCount == 0 || !(longest > 0.0)) return {1, 1, 1};
    double perUnit = std::cbrt(options.cellsPerPrimitive * double(primCount)) / longest;
    std::array<int, 3> resolution;
    for (int a = 0; a < 3; ++a)
        resolution[a] = int(std::clamp<long>(std::lround(double(extent[a]) * perUnit), 1, options.maxResolution));
    return resolution;
}

GridCell expectedCell(const worker::GridFrame& frame, const Vec3& p) {
    GridCell cell;
    for (int a = 0; a < 3; ++a) {
        float f = std::floor((p[a] - frame.bounds.lower[a]) * frame.inverseWidth[a]);
        int last = frame.resolution[a] - 1;
        cell[a] = f >= float(last) ? last : f > 0.0f ? int(f) : 0;
    }
    return cell;
}

worker::GridFrame frameOf(const Bounds3f& bounds, const std::array<int, 3>& resolution) {
    worker::GridFrame frame{bounds, resolution, Vec3(0.0f), Vec3(0.0f)};
    Vec3 extent = bounds.diagonal();
    for (int a = 0; a < 3; ++a) {
        frame.cellWidth[a] = extent[a] / float(resolution[a]);
        frame.inverseWidth[a] = extent[a] > 0.0f ? float(resolution[a]) / extent[a] : 0.0f;
    }
    return frame;
}

worker::GridFrame expectedFrame(std::span<const Bounds3f> primBounds, const GridOptions& options) {
    Bounds3f bounds;
    uint64_t placeable = 0;
    for (const Bounds3f& box : primBounds)
        if (isPlaceable(box)) {
            bounds.extend(box);
            ++placeable;
        }
    if (placeable == 0) bounds = Bounds3f(Vec3(0.0f));
    return frameOf(bounds, expectedResolution(bounds, placeable, options));
}

std::optional<std::vector<GridCell>> exactCellWalk(const worker::GridFrame& frame, const Ray& ray, float tEnter, float tExit) {
    double t0 = tEnter, t1 = tExit, scale = std::max({1.0, std::abs(t0), std::abs(t1)});
    double tolerance = kAmbiguity * scale;
    GridCell cell;
    struct Crossing {
        double t;
        int axis;
    };
    std::vector<Crossing> crossings;
    for (int a = 0; a < 3; ++a) {
        double lower = frame.bounds.lower[a], width = frame.cellWidth[a];
        double o = ray.origin[a], d = ray.direction[a];
        double position = (o + t0 * d - lower) / width;  // in cells
        // The start point on an interior boundary (other than where the ray enters) is ambiguous.
        double nearest = std::round(position);
        if (nearest > 0 && nearest < frame.resolution[a] && std::abs(position - nearest) < kAmbiguity) return std::nullopt;
        cell[a] = std::clamp(int(std::floor(position)), 0, frame.resolution[a] - 1);
        if (d == 0.0) continue;
        int step = d < 0 ? -1 : 1;
        for (int boundary = cell[a] + (step > 0 ? 1 : 0); boundary >= 0 && boundary <= frame.resolution[a]; boundary += step) {
            double t = (lower + boundary * width - o) / d;
            if (t > t1 + tolerance) break;
            crossings.push_back({t, a});
        }
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
    std::vector<GridCell> cells{cell};
    for (size_t i = 0; i < crossings.size(); ++i) {
        const Crossing& c = crossings[i];
        int axis = c.axis;
        cell[axis] += ray.direction[axis] < 0 ? -1 : 1;
        bool leaves = cell[axis] < 0 || cell[axis] >= frame.resolution[axis];
        bool nearOther = (i > 0 && c.t - crossings[i - 1].t < tolerance) ||
                         (i + 1 < crossings.size() && crossings[i + 1].t - c.t < tolerance);
        // The crossing out of the grid lies at tExit by construction; any other crossing that
        // close to an end, or to another crossing, may fall on either side in float.
        if (nearOther || std::abs(c.t - t0) < tolerance || (!leaves && std::abs(c.t - t1) < tolerance)) return std::nullopt;
        if (leaves || c.t > t1) break;
        cells.push_back(cell);
    }
    return cells;
}

}  // namespace rtlab::grader
