// Reference solution: solid angles of a cone, a sphere, a triangle and a rectangle, and the
// integral of dOmega = sin(theta) dtheta dphi (docs/a6-radiometry.md#solid-angle).
#include "framework/interface/a6_radiometry.h"

#include <cmath>
#include <numbers>

namespace rtlab {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

// 2 pi (1 - cos a) written as 4 pi sin^2(a/2): the difference 1 - cos a cancels every digit
// for a cone as narrow as a star seen from here.
double solidAngleOfCone(double halfAngle) {
    double s = std::sin(halfAngle / 2.0);
    return 4.0 * kPi * s * s;
}

double solidAngleOfSphere(double radius, double distance) {
    if (distance <= radius) return 4.0 * kPi;
    double sin2 = (radius / distance) * (radius / distance);
    // 1 - cos a = sin^2 a / (1 + cos a), without cancellation.
    return 2.0 * kPi * sin2 / (1.0 + std::sqrt(1.0 - sin2));
}

double solidAngleOfTriangle(const DVec3& p, const DVec3& a, const DVec3& b, const DVec3& c) {
    DVec3 A = a - p, B = b - p, C = c - p;
    double la = glm::length(A), lb = glm::length(B), lc = glm::length(C);
    double numerator = std::abs(glm::dot(A, glm::cross(B, C)));
    double denominator = la * lb * lc + glm::dot(A, B) * lc + glm::dot(A, C) * lb + glm::dot(B, C) * la;
    // atan2 keeps the quadrant: a negative denominator means Omega / 2 lies beyond pi / 2.
    return 2.0 * std::atan2(numerator, denominator);
}

// Two triangles sharing the diagonal; seen from any point off their common plane both lie on
// the same side, so their solid angles add.
double solidAngleOfRectangle(const DVec3& p, const DVec3& corner, const DVec3& u, const DVec3& v) {
    return solidAngleOfTriangle(p, corner, corner + u, corner + u + v) +
           solidAngleOfTriangle(p, corner, corner + u + v, corner + v);
}

double integrateOverSphere(const std::function<double(double theta, double phi)>& f, int thetaSteps, int phiSteps) {
    double dTheta = kPi / thetaSteps, dPhi = 2.0 * kPi / phiSteps;
    double sum = 0.0;
    for (int i = 0; i < thetaSteps; ++i) {
        double theta = (i + 0.5) * dTheta;
        // The cell's solid angle: a ring narrows towards the poles as sin(theta).
        double cell = std::sin(theta) * dTheta * dPhi;
        for (int j = 0; j < phiSteps; ++j) sum += f(theta, (j + 0.5) * dPhi) * cell;
    }
    return sum;
}

}  // namespace rtlab
