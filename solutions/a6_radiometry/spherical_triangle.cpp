// Reference solution: uniform directions inside a spherical triangle, after Arvo, "Stratified
// Sampling of Spherical Triangles" (SIGGRAPH 1995) (docs/a6-radiometry.md#spherical-triangles).
// In double: the formula for q divides differences of nearly equal terms for thin triangles.
#include "framework/interface/a6_radiometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtlab {
namespace {

// The angle between two vectors, from atan2 of the sine and cosine: accurate near 0 and pi,
// where acos of a rounded dot product is not.
double angleBetween(const DVec3& a, const DVec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// The part of v orthogonal to the unit vector w, normalised: the tangent at w of the great
// circle from w towards v.
DVec3 tangentTowards(const DVec3& w, const DVec3& v) { return glm::normalize(v - glm::dot(v, w) * w); }

}  // namespace

DirectionSample sampleSphericalTriangle(const Vec3& p, const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u) {
    DVec3 A = glm::normalize(DVec3(p0) - DVec3(p));
    DVec3 B = glm::normalize(DVec3(p1) - DVec3(p));
    DVec3 C = glm::normalize(DVec3(p2) - DVec3(p));
    // The angle at a vertex is the angle between the planes (through p) of its two edges.
    DVec3 nAB = glm::cross(A, B), nBC = glm::cross(B, C), nCA = glm::cross(C, A);
    double alpha = angleBetween(nAB, -nCA), beta = angleBetween(nBC, -nAB), gamma = angleBetween(nCA, -nBC);
    // Girard: the area of a spherical triangle is its angle excess.
    double area = alpha + beta + gamma - std::numbers::pi;
    if (!(area > 0.0)) return {Vec3(0.0f, 0.0f, 1.0f), 0.0f};

    // The sub-triangle A, B, C' of area u.x * area: q = cos of the arc from A to C'.
    double subArea = u.x * area;
    double s = std::sin(subArea - alpha), t = std::cos(subArea - alpha);
    double uu = t - std::cos(alpha);
    double v = s + std::sin(alpha) * glm::dot(A, B);
    double q = ((v * t - uu * s) * std::cos(alpha) - v) / ((v * s + uu * t) * std::sin(alpha));
    q = std::isfinite(q) ? std::clamp(q, -1.0, 1.0) : 1.0;
    DVec3 cPrime = q * A + std::sqrt(1.0 - q * q) * tangentTowards(A, C);
    // On the arc from B to C', uniform in the cosine to B: the sub-triangle's area grows
    // linearly with that cosine.
    double z = 1.0 - u.y * (1.0 - glm::dot(cPrime, B));
    DVec3 direction = z * B + std::sqrt(std::max(0.0, 1.0 - z * z)) * tangentTowards(B, cPrime);
    return {Vec3(direction), static_cast<float>(1.0 / area)};
}

}  // namespace rtlab
