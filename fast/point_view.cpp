#include "fast/point_view.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

constexpr double kUnitRoundoff = 0x1p-24;  // u: float's relative rounding
constexpr double kMarginFactor = 64.0;     // margins in units of u reach
constexpr double kMinCosine = 0.2;         // the bounds' corners within 78 degrees of the axis
constexpr double kMinNearness = 1e-3;      // triangles at least this share of the reach away
constexpr double kCellsPerTriangle = 4.0;
constexpr size_t kMaxEntriesPerTriangle = 8;

// The distance from p to the nearest point of box.
double distanceTo(const DVec3& p, const DVec3& lower, const DVec3& upper) {
    DVec3 outside = glm::max(glm::max(lower - p, p - upper), DVec3(0.0));
    return glm::length(outside);
}

struct Entry {
    double reach;  // the triangle's nearest distance to the point
    uint32_t prim;
};

}  // namespace

bool PointView::project(const DVec3& w, double& x, double& y) const {
    double along = glm::dot(w, axis_);
    if (!(along > 0.0)) return false;
    x = glm::dot(w, u_) / along;
    y = glm::dot(w, v_) / along;
    return true;
}

std::unique_ptr<PointView> PointView::make(const PrimitiveSet& primitives, const Vec3& point, const Accelerator& fallback) {
    const uint32_t n = primitives.triangleCount();
    if (n == 0 || n != primitives.size()) return nullptr;
    std::unique_ptr<PointView> view(new PointView(point, fallback));
    Bounds3f bounds;
    for (uint32_t prim = 0; prim < n; ++prim)
        for (const Vec3& vertex : primitives.triangle(prim)) bounds.extend(vertex);
    double minCosine = 0.0, reach = 0.0;
    if (!view->frameBounds(bounds, minCosine, reach)) return nullptr;
    // A change of direction by an angle a moves a projected point by up to a / cos^2 of its
    // angle to the axis; twice that, for the directions a margin away from the cone's.
    std::vector<Rect> rects;
    if (!view->rectangles(primitives, 2.0 / (minCosine * minCosine), reach, rects)) return nullptr;
    view->sizeGrid(rects);
    view->fillCells(primitives, rects);
    return view;
}

bool PointView::frameBounds(const Bounds3f& bounds, double& minCosine, double& reach) {
    const DVec3 origin(point_);
    DVec3 towards = DVec3(bounds.centre()) - origin;
    double length = glm::length(towards);
    if (!(length > 0.0) || !std::isfinite(length)) return false;
    axis_ = towards / length;
    DVec3 helper = std::abs(axis_.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0);
    u_ = glm::normalize(glm::cross(axis_, helper));
    v_ = glm::cross(axis_, u_);
    minCosine = 1.0;
    reach = 0.0;
    for (int i = 0; i < 8; ++i) {
        DVec3 corner(bounds[i & 1].x, bounds[(i >> 1) & 1].y, bounds[(i >> 2) & 1].z);
        DVec3 w = corner - origin;
        double distance = glm::length(w);
        if (!(distance > 0.0) || !std::isfinite(distance)) return false;
        minCosine = std::min(minCosine, glm::dot(w, axis_) / distance);
        reach = std::max(reach, distance);
    }
    slack_ = kMarginFactor * kUnitRoundoff * reach;
    return minCosine > kMinCosine;
}

bool PointView::rectangles(const PrimitiveSet& primitives, double planeScale, double reach, std::vector<Rect>& rects) const {
    const DVec3 origin(point_);
    rects.resize(primitives.triangleCount());
    for (uint32_t prim = 0; prim < primitives.triangleCount(); ++prim) {
        DVec3 lower(kInfinity), upper(-kInfinity);
        Rect rect{kInfinity, kInfinity, -kInfinity, -kInfinity, 0.0};
        for (const Vec3& vertex : primitives.triangle(prim)) {
            double x = 0.0, y = 0.0;
            if (!project(DVec3(vertex) - origin, x, y)) return false;
            rect.x0 = std::min(rect.x0, x);
            rect.y0 = std::min(rect.y0, y);
            rect.x1 = std::max(rect.x1, x);
            rect.y1 = std::max(rect.y1, y);
            lower = glm::min(lower, DVec3(vertex));
            upper = glm::max(upper, DVec3(vertex));
        }
        rect.reach = distanceTo(origin, lower, upper);
        if (!(rect.reach >= kMinNearness * reach)) return false;
        double margin = planeScale * kMarginFactor * kUnitRoundoff * reach / rect.reach;
        rects[prim] = {rect.x0 - margin, rect.y0 - margin, rect.x1 + margin, rect.y1 + margin, rect.reach};
    }
    return true;
}

void PointView::sizeGrid(const std::vector<Rect>& rects) {
    double x0 = kInfinity, y0 = kInfinity, x1 = -kInfinity, y1 = -kInfinity;
    for (const Rect& rect : rects) {
        x0 = std::min(x0, rect.x0);
        y0 = std::min(y0, rect.y0);
        x1 = std::max(x1, rect.x1);
        y1 = std::max(y1, rect.y1);
    }
    // Square cells, about kCellsPerTriangle per triangle, or larger ones while the lists would
    // hold more than kMaxEntriesPerTriangle entries a triangle (long thin triangles, whose
    // rectangles cover many cells: the engine's).
    const double width = x1 - x0, height = y1 - y0;
    gridX_ = x0;
    gridY_ = y0;
    cellSize_ = std::max(std::sqrt(width * height / (kCellsPerTriangle * rects.size())), 1e-9 * std::max(width, height));
    for (;;) {
        columns_ = std::clamp(int(std::ceil(width / cellSize_)), 1, 4096);
        rows_ = std::clamp(int(std::ceil(height / cellSize_)), 1, 4096);
        cellSize_ = std::max(width / columns_, height / rows_);
        inverseCellSize_ = 1.0 / cellSize_;
        size_t entries = 0;
        for (const Rect& rect : rects) entries += size_t(columnsOf(rect)) * size_t(rowsOf(rect));
        if (entries <= kMaxEntriesPerTriangle * rects.size() || (columns_ == 1 && rows_ == 1)) break;
        cellSize_ *= 1.5;
    }
}

void PointView::fillCells(const PrimitiveSet& primitives, const std::vector<Rect>& rects) {
    // Each cell's triangles, counted, placed, then sorted nearest first.
    const size_t cells = size_t(columns_) * rows_;
    auto eachCell = [this](const Rect& rect, auto&& visit) {
        int x0 = cellOf(rect.x0, gridX_, columns_), y0 = cellOf(rect.y0, gridY_, rows_);
        for (int y = y0; y < y0 + rowsOf(rect); ++y)
            for (int x = x0; x < x0 + columnsOf(rect); ++x) visit(size_t(y) * columns_ + x);
    };
    std::vector<uint32_t> entryStart(cells + 1, 0);
    for (const Rect& rect : rects) eachCell(rect, [&](size_t cell) { ++entryStart[cell + 1]; });
    for (size_t cell = 0; cell < cells; ++cell) entryStart[cell + 1] += entryStart[cell];
    std::vector<Entry> list(entryStart.back());
    std::vector<uint32_t> fill(entryStart.begin(), entryStart.end() - 1);
    for (uint32_t prim = 0; prim < rects.size(); ++prim)
        eachCell(rects[prim], [&](size_t cell) { list[fill[cell]++] = Entry{rects[prim].reach, prim}; });

    // Four triangles to a packet, a cell's packets in a row; a packet's reach is its first
    // triangle's, the nearest.
    cellStart_.assign(cells + 1, 0);
    for (size_t cell = 0; cell < cells; ++cell) {
        uint32_t count = entryStart[cell + 1] - entryStart[cell];
        cellStart_[cell + 1] = cellStart_[cell] + (count + TrianglePacket::kLanes - 1) / TrianglePacket::kLanes;
    }
    packets_.resize(cellStart_.back());
    packetReach_.resize(cellStart_.back());
    for (size_t cell = 0; cell < cells; ++cell) {
        Entry* first = list.data() + entryStart[cell];
        Entry* last = list.data() + entryStart[cell + 1];
        std::sort(first, last, [](const Entry& a, const Entry& c) { return a.reach < c.reach || (a.reach == c.reach && a.prim < c.prim); });
        uint32_t packet = cellStart_[cell];
        for (Entry* e = first; e < last; e += TrianglePacket::kLanes, ++packet) {
            uint32_t ids[TrianglePacket::kLanes];
            int count = int(std::min<ptrdiff_t>(TrianglePacket::kLanes, last - e));
            for (int lane = 0; lane < count; ++lane) ids[lane] = e[lane].prim;
            packets_[packet].fill(primitives, std::span<const uint32_t>(ids, size_t(count)));
            // Rounded down, so that a float comparison never skips a packet the double one keeps.
            packetReach_[packet] = std::nextafter(float(e->reach), 0.0f);
        }
    }
}

int PointView::columnsOf(const Rect& rect) const {
    return cellOf(rect.x1, gridX_, columns_) - cellOf(rect.x0, gridX_, columns_) + 1;
}

int PointView::rowsOf(const Rect& rect) const {
    return cellOf(rect.y1, gridY_, rows_) - cellOf(rect.y0, gridY_, rows_) + 1;
}

// The build places a triangle's rectangle and a query its direction by the same arithmetic,
// (coordinate - grid corner) * (1 / cell side), which never decreases as the coordinate grows:
// a direction inside a rectangle lands in one of the rectangle's cells.
int PointView::cellOf(double value, double gridStart, int cells) const {
    return std::clamp(int(std::floor((value - gridStart) * inverseCellSize_)), 0, cells - 1);
}

long PointView::cellAt(double x, double y) const {
    const double cx = (x - gridX_) * inverseCellSize_, cy = (y - gridY_) * inverseCellSize_;
    // Before the grid's corner no triangle's widened rectangle holds the direction, nor well
    // beyond its far sides; at the far sides a rounded product may exceed the cell count a
    // little, and clamps to the last cell.
    if (!(cx >= 0.0 && cy >= 0.0 && cx <= columns_ + 0.5 && cy <= rows_ + 0.5)) return -1;
    return long(std::min(int(cy), rows_ - 1)) * columns_ + std::min(int(cx), columns_ - 1);
}

Hit PointView::intersect(const Ray& ray, TraversalStats& stats) const {
    double x = 0.0, y = 0.0;
    if (!(ray.tMin >= 0.0f) || ray.origin != point_ || !project(DVec3(ray.direction), x, y))
        return fallback_.intersect(ray, stats);
    ++stats.rays;
    Hit hit;
    hit.t = ray.tMax;
    if (long cell = cellAt(x, y); cell >= 0) {
        ++stats.nodeVisits;  // the cell
        const ShearedRay sheared(ray);
        const double length = glm::length(DVec3(ray.direction));
        // A hit at t lies t |direction| from the point, give or take the slack: a packet whose
        // nearest triangle is farther than the nearest hit so far holds no nearer one.
        for (uint32_t p = cellStart_[cell]; p < cellStart_[cell + 1]; ++p) {
            if (hit.found() && packetReach_[p] > double(hit.t) * length + slack_) break;
            stats.primitiveTests += TrianglePacket::kLanes;
            const TrianglePacket& packet = packets_[p];
            if (PacketHit nearest = sheared.closest(packet, hit.t); nearest.lane >= 0)
                hit = Hit{nearest.hit.t, packet.prim[nearest.lane], nearest.hit.b1, nearest.hit.b2};
        }
    }
    if (!hit.found()) hit.t = kInfinity;
    return hit;
}

bool PointView::occluded(const Ray& ray, TraversalStats& stats) const {
    double x = 0.0, y = 0.0;
    if (!(ray.tMin >= 0.0f && ray.tMax <= 1.0f) || ray.direction != point_ - ray.origin ||
        !project(DVec3(ray.origin) - DVec3(point_), x, y))
        return fallback_.occluded(ray, stats);
    ++stats.rays;
    const long cell = cellAt(x, y);
    if (cell < 0) return false;
    ++stats.nodeVisits;  // the cell
    // A triangle farther from the point than the origin (by more than the slack) is behind the
    // whole segment.
    const double limit = glm::length(DVec3(ray.origin) - DVec3(point_)) + slack_;
    const ShearedRay sheared(ray);
    for (uint32_t p = cellStart_[cell]; p < cellStart_[cell + 1] && packetReach_[p] <= limit; ++p) {
        stats.primitiveTests += TrianglePacket::kLanes;
        if (sheared.anyHit(packets_[p], ray.tMax)) return true;
    }
    return false;
}

}  // namespace rtlab
