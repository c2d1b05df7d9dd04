// The histograms a6's sampler tests count samples in, and the counts each target distribution
// expects in them (docs/a6-radiometry.md#how-the-grader-checks-it). Every cell's expected count
// is exact: an integral of the target density over the cell in closed form.
#pragma once

#include "framework/core/vec.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace rtlab::grader {

// Directions by (z, phi): zBands equal bands of z over [zMin, 1] times phiSectors equal sectors
// of phi. Every band of z is a ring of equal area (Archimedes), so every cell is too. One more
// cell, the last, holds the directions outside [zMin, 1]: their target density is 0.
struct DirectionBins {
    double zMin = -1.0;
    int zBands = 20, phiSectors = 40;

    size_t cells() const { return static_cast<size_t>(zBands) * phiSectors + 1; }
    size_t cellOf(const Vec3& direction) const;
    // Counts for n samples of a distribution uniform in phi whose z has the distribution
    // function F on [zMin, 1] (F(zMin) = 0, F(1) = 1).
    std::vector<double> expected(double n, const std::function<double(double z)>& F) const;
    // "z in [a, b], phi in [c, d]" for a report.
    std::string describe(size_t cell) const;
};

// Points of a triangle by their barycentric coordinates (b1, b2) of p1 and p2: the k^2
// congruent sub-triangles of the lattice of step 1/k; one more cell, the last, holds points
// off the triangle (beyond 1e-5 of its size).
struct TriangleBins {
    DVec3 p0, p1, p2;
    int k = 24;

    size_t cells() const { return static_cast<size_t>(k) * k + 1; }
    size_t cellOf(const DVec3& point) const;
    // Where the ray from `from` along `direction` meets the triangle's plane (for directions).
    size_t cellOfDirection(const DVec3& from, const DVec3& direction) const;
    // The sub-triangles' corners, in cell order.
    std::vector<std::array<DVec3, 3>> subTriangles() const;
    std::string describe(size_t cell) const;
};

}  // namespace rtlab::grader
