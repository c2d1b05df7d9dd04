#include "grader/a6_radiometry/sampler_histograms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace rtlab::grader {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// How far a point may lie off its triangle: 1e-5 of the triangle's size plus 8 float ulps of
// its coordinates (float rounding of a sampled point, not a wrong sample).
constexpr double kOffTriangle = 1e-5;
constexpr double kFloatUlps = 8.0 * 0x1p-24;

// The first lattice index of row i (b1 in [i/k, (i+1)/k)): each earlier row r holds k - r lower
// and k - r - 1 upper sub-triangles.
size_t rowStart(int i, int k) { return static_cast<size_t>(i) * (2 * k - i); }

}  // namespace

size_t DirectionBins::cellOf(const Vec3& direction) const {
    double z = direction.z;
    if (!(z >= zMin && z <= 1.0)) return cells() - 1;
    int band = std::min(zBands - 1, static_cast<int>((z - zMin) / (1.0 - zMin) * zBands));
    double phi = std::atan2(double(direction.y), double(direction.x));
    if (phi < 0.0) phi += kTwoPi;
    int sector = std::min(phiSectors - 1, static_cast<int>(phi / kTwoPi * phiSectors));
    return static_cast<size_t>(band) * phiSectors + sector;
}

std::vector<double> DirectionBins::expected(double n, const std::function<double(double)>& F) const {
    std::vector<double> counts(cells(), 0.0);
    for (int band = 0; band < zBands; ++band) {
        double a = zMin + (1.0 - zMin) * band / zBands, b = zMin + (1.0 - zMin) * (band + 1) / zBands;
        for (int sector = 0; sector < phiSectors; ++sector)
            counts[static_cast<size_t>(band) * phiSectors + sector] = n * (F(b) - F(a)) / phiSectors;
    }
    return counts;
}

std::string DirectionBins::describe(size_t cell) const {
    if (cell == cells() - 1) return "outside the sampled range of z";
    int band = static_cast<int>(cell) / phiSectors, sector = static_cast<int>(cell) % phiSectors;
    char text[160];
    std::snprintf(text, sizeof text, "z in [%.3g, %.3g], phi in [%.3g, %.3g] rad", zMin + (1.0 - zMin) * band / zBands,
                  zMin + (1.0 - zMin) * (band + 1) / zBands, kTwoPi * sector / phiSectors, kTwoPi * (sector + 1) / phiSectors);
    return text;
}

size_t TriangleBins::cellOf(const DVec3& point) const {
    DVec3 e1 = p1 - p0, e2 = p2 - p0, w = point - p0, n = glm::cross(e1, e2);
    double area2 = glm::length(n);
    double magnitude = std::max({glm::length(p0), glm::length(p1), glm::length(p2)});
    double slack = kOffTriangle * std::sqrt(area2) + kFloatUlps * magnitude;
    if (!(std::abs(glm::dot(w, n)) / area2 <= slack)) return cells() - 1;
    // Barycentrics by the normal equations of w = b1 e1 + b2 e2; the slack in barycentric units
    // is the distance over the shortest altitude, 2 area / the longest edge.
    double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    double w1 = glm::dot(w, e1), w2 = glm::dot(w, e2), det = d11 * d22 - d12 * d12;
    double b1 = (d22 * w1 - d12 * w2) / det, b2 = (d11 * w2 - d12 * w1) / det;
    double longest = std::sqrt(std::max({d11, d22, glm::dot(p2 - p1, p2 - p1)}));
    double tolerance = slack * longest / area2;
    if (!(b1 >= -tolerance && b2 >= -tolerance && b1 + b2 <= 1.0 + tolerance)) return cells() - 1;
    double x = std::clamp(b1, 0.0, 1.0) * k, y = std::clamp(b2, 0.0, 1.0) * k;
    int i = std::min(k - 1, static_cast<int>(x));
    int j = std::min(k - 1 - i, static_cast<int>(y));
    bool upper = (x - i) + (y - j) > 1.0 && i + j < k - 1;
    return rowStart(i, k) + 2 * static_cast<size_t>(j) + (upper ? 1 : 0);
}

size_t TriangleBins::cellOfDirection(const DVec3& from, const DVec3& direction) const {
    DVec3 n = glm::cross(p1 - p0, p2 - p0);
    double t = glm::dot(n, p0 - from) / glm::dot(n, direction);
    if (!(t > 0.0) || !std::isfinite(t)) return cells() - 1;
    return cellOf(from + t * direction);
}

std::vector<std::array<DVec3, 3>> TriangleBins::subTriangles() const {
    auto at = [&](int i, int j) { return p0 + (double(i) / k) * (p1 - p0) + (double(j) / k) * (p2 - p0); };
    std::vector<std::array<DVec3, 3>> out;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k - i; ++j) {
            out.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
            if (i + j < k - 1) out.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return out;
}

std::string TriangleBins::describe(size_t cell) const {
    if (cell == cells() - 1) return "off the triangle";
    auto corners = subTriangles()[cell];
    DVec3 c = (corners[0] + corners[1] + corners[2]) / 3.0;
    char text[160];
    std::snprintf(text, sizeof text, "the sub-triangle around (%.3g, %.3g, %.3g)", c.x, c.y, c.z);
    return text;
}

}  // namespace rtlab::grader
