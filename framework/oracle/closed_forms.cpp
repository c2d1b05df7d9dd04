#include "framework/oracle/closed_forms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rtlab {
namespace {

double angleBetween(const DVec3& a, const DVec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

}  // namespace

double triangleSolidAngleByExcess(const DVec3& x, const DVec3& a, const DVec3& b, const DVec3& c) {
    DVec3 A = a - x, B = b - x, C = c - x;
    // The angle at each vertex of the spherical triangle is the dihedral angle between the two
    // planes (through x) of the edges that meet there.
    double atA = angleBetween(glm::cross(A, B), glm::cross(A, C));
    double atB = angleBetween(glm::cross(B, C), glm::cross(B, A));
    double atC = angleBetween(glm::cross(C, A), glm::cross(C, B));
    return atA + atB + atC - std::numbers::pi;
}

double polygonIrradiance(const DVec3& x, const DVec3& n, std::span<const DVec3> polygon) {
    double sum = 0.0;
    for (size_t k = 0; k < polygon.size(); ++k) {
        DVec3 a = polygon[k] - x, b = polygon[(k + 1) % polygon.size()] - x;
        DVec3 g = glm::cross(a, b);
        double length = glm::length(g);
        if (length > 0.0) sum += angleBetween(a, b) * glm::dot(n, g / length);
    }
    return 0.5 * std::abs(sum);
}

std::vector<DVec3> clipPolygon(std::span<const DVec3> polygon, const DVec3& point, const DVec3& normal) {
    std::vector<DVec3> kept;
    for (size_t k = 0; k < polygon.size(); ++k) {
        const DVec3& a = polygon[k];
        const DVec3& b = polygon[(k + 1) % polygon.size()];
        double da = glm::dot(a - point, normal), db = glm::dot(b - point, normal);
        if (da >= 0.0) kept.push_back(a);
        // An edge that crosses the plane contributes the crossing point.
        if ((da >= 0.0) != (db >= 0.0)) kept.push_back(a + (da / (da - db)) * (b - a));
    }
    return kept;
}

double sphereIrradiance(const DVec3& x, const DVec3& n, const DVec3& centre, double radius) {
    DVec3 toCentre = centre - x;
    double d = glm::length(toCentre);
    if (!(d > radius)) return std::numeric_limits<double>::quiet_NaN();
    double sinAlpha = radius / d;
    double cosTheta = glm::dot(n, toCentre) / d;
    if (std::acos(std::min(1.0, cosTheta)) + std::asin(sinAlpha) > std::numbers::pi / 2)
        return std::numeric_limits<double>::quiet_NaN();
    return std::numbers::pi * sinAlpha * sinAlpha * cosTheta;
}

}  // namespace rtlab
