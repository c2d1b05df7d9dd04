// Reference solution: samplers by inversion of their distribution functions, each returning
// the density of what it drew, and the change from area to solid-angle density
// (docs/a6-radiometry.md#samplers).
#include "framework/interface/a6_radiometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtlab {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The direction at height z and azimuth phi on the unit sphere.
Vec3 direction(float z, float phi) {
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

}  // namespace

// Archimedes: a sphere's area between two heights grows linearly with their distance, so a
// uniform z (not a uniform theta) spreads the points evenly.
DirectionSample sampleUniformSphere(Vec2 u) {
    return {direction(1.0f - 2.0f * u.x, 2.0f * kPi * u.y), 1.0f / (4.0f * kPi)};
}

DirectionSample sampleUniformHemisphere(Vec2 u) {
    return {direction(u.x, 2.0f * kPi * u.y), 1.0f / (2.0f * kPi)};
}

// Malley: uniform on the disk, then lifted onto the hemisphere; the projection of a
// cosine-weighted direction onto the disk is uniform.
DirectionSample sampleCosineHemisphere(Vec2 u) {
    float z = std::sqrt(std::max(0.0f, 1.0f - u.x));
    return {direction(z, 2.0f * kPi * u.y), z / kPi};
}

DirectionSample sampleUniformCone(Vec2 u, float cosThetaMax) {
    float z = 1.0f - u.x * (1.0f - cosThetaMax);
    return {direction(z, 2.0f * kPi * u.y), 1.0f / (2.0f * kPi * (1.0f - cosThetaMax))};
}

// The square root folds the unit square onto the triangle without crowding the corner p0:
// the share of the area within barycentric distance s of p0's opposite edge grows as s^2.
PointSample sampleUniformTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u) {
    float s = std::sqrt(u.x);
    float b0 = 1.0f - s, b1 = u.y * s, b2 = 1.0f - b0 - b1;
    float area = 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
    return {b0 * p0 + b1 * p1 + b2 * p2, area > 0.0f ? 1.0f / area : 0.0f};
}

// dOmega = dA cos(theta_light) / d^2, so a density per area becomes one per steradian by
// d^2 / cos; the sign of the cosine says only which side faces the point.
float areaToSolidAnglePdf(float pdfArea, float distanceSquared, float cosThetaLight) {
    float c = std::abs(cosThetaLight);
    return c > 0.0f ? pdfArea * distanceSquared / c : kInfinity;
}

}  // namespace rtlab
