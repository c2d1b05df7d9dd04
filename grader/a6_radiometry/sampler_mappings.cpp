#include "grader/a6_radiometry/sampler_mappings.h"

#include "framework/oracle/closed_forms.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtlab::grader {
namespace {

using worker::Sampler;

constexpr double kPi = std::numbers::pi;
constexpr double kDirectionTolerance = 2e-3;
constexpr double kPointTolerance = 2e-3;  // of the triangle's longest edge
constexpr double kFloatUlps = 8.0 * 0x1p-24;

// The unit direction at height z and azimuth phi about +z.
DVec3 direction(double z, double phi) {
    double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// The unit tangent at the unit vector w of the great circle from w towards v.
DVec3 towards(const DVec3& w, const DVec3& v) { return glm::normalize(v - glm::dot(v, w) * w); }

DVec3 sphericalTriangle(const worker::SamplerCall& c, double ux, double uy) {
    // A, B, C: the unit directions from p to the corners, as in the contract.
    DVec3 p(c.p);
    DVec3 A = glm::normalize(DVec3(c.p0) - p), B = glm::normalize(DVec3(c.p1) - p), C = glm::normalize(DVec3(c.p2) - p);
    const DVec3 centre(0.0);
    // The area of A, B, C' grows monotonically as C' moves along the arc from A to C.
    DVec3 tangent = towards(A, C);
    double arc = std::atan2(glm::length(glm::cross(A, C)), glm::dot(A, C));
    double target = ux * triangleSolidAngleByExcess(centre, A, B, C);
    auto along = [&](double angle) { return std::cos(angle) * A + std::sin(angle) * tangent; };
    double lo = 0.0, hi = arc;
    for (int i = 0; i < 60; ++i) {
        double mid = 0.5 * (lo + hi);
        if (triangleSolidAngleByExcess(centre, A, B, along(mid)) < target) lo = mid;
        else hi = mid;
    }
    DVec3 cPrime = along(0.5 * (lo + hi));
    double z = 1.0 - uy * (1.0 - glm::dot(cPrime, B));
    return z * B + std::sqrt(std::max(0.0, 1.0 - z * z)) * towards(B, cPrime);
}

}  // namespace

DVec3 pinnedSample(const worker::SamplerCall& c, Vec2 u) {
    double ux = u.x, uy = u.y, phi = 2.0 * kPi * uy;
    switch (c.sampler) {
        case Sampler::UniformSphere: return direction(1.0 - 2.0 * ux, phi);
        case Sampler::UniformHemisphere: return direction(ux, phi);
        case Sampler::CosineHemisphere: return direction(std::sqrt(1.0 - ux), phi);  // r = sqrt(u.x), z = sqrt(1 - r^2)
        case Sampler::UniformCone: return direction(1.0 - ux * (1.0 - double(c.cosThetaMax)), phi);
        case Sampler::UniformTriangle: {
            double s = std::sqrt(ux), b0 = 1.0 - s, b1 = uy * s;
            return b0 * DVec3(c.p0) + b1 * DVec3(c.p1) + (1.0 - b0 - b1) * DVec3(c.p2);
        }
        case Sampler::SphericalTriangle: return sphericalTriangle(c, ux, uy);
    }
    return DVec3(std::nan(""));
}

double pinnedTolerance(const worker::SamplerCall& c) {
    if (c.sampler != Sampler::UniformTriangle) return kDirectionTolerance;
    DVec3 p0(c.p0), p1(c.p1), p2(c.p2);
    double longest = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    double magnitude = std::max({glm::length(p0), glm::length(p1), glm::length(p2)});
    return kPointTolerance * longest + kFloatUlps * magnitude;
}

}  // namespace rtlab::grader
