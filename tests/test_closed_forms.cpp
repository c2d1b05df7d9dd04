// framework/oracle/closed_forms: Lambert's contour formula against the form factor of a
// rectangle and against quadrature, polygon clipping, the sphere light, and Girard's solid
// angle against a6's Van Oosterom-Strackee (the reference solution) and against the octant.
#include "framework/core/pcg32.h"
#include "framework/interface/a6_radiometry.h"
#include "framework/oracle/closed_forms.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace rtlab;

namespace {

constexpr double kPi = std::numbers::pi;

// The form factor from a point to a rectangle a x b at distance c, with the perpendicular foot
// at a corner (Howell's catalogue, C-11, written for unit c): the irradiance per unit radiance
// is pi times it.
double cornerIrradiance(double a, double b, double c) {
    double A = a / c, B = b / c;
    double f = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
               (2 * kPi);
    return kPi * f;
}

// E = integral of cos(theta) / d^2 cos(theta_light) dA over a polygon in the plane y = h facing
// down, by the midpoint rule on a grid: independent of the contour formula.
double quadratureUnderSquare(const DVec3& x, double half, double h, int steps) {
    double sum = 0.0, cell = 2 * half / steps;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            DVec3 y(-half + (i + 0.5) * cell, h, -half + (j + 0.5) * cell);
            DVec3 d = y - x;
            double r2 = glm::dot(d, d), cosTheta = d.y / std::sqrt(r2);
            sum += cosTheta * cosTheta / r2 * cell * cell;  // both cosines are d.y / r here
        }
    return sum;
}

}  // namespace

TEST_CASE("closed forms: the contour formula under a square light, at its centre and off it") {
    std::vector<DVec3> square{{-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {-0.5, 1, 0.5}};
    // Under the centre: four 0.5 x 0.5 corner rectangles at distance 1.
    CHECK(polygonIrradiance({0, 0, 0}, {0, 1, 0}, square) == doctest::Approx(4 * cornerIrradiance(0.5, 0.5, 1.0)).epsilon(1e-12));
    CHECK(polygonIrradiance({0, 0, 0}, {0, 1, 0}, square) == doctest::Approx(0.752274688454).epsilon(1e-11));
    // Under a corner: one 1 x 1 rectangle.
    CHECK(polygonIrradiance({0.5, 0, 0.5}, {0, 1, 0}, square) == doctest::Approx(cornerIrradiance(1, 1, 1)).epsilon(1e-12));
    // Off to the side, against quadrature.
    DVec3 x(1.3, 0, -0.4);
    CHECK(polygonIrradiance(x, {0, 1, 0}, square) == doctest::Approx(quadratureUnderSquare(x, 0.5, 1, 1000)).epsilon(1e-6));
}

TEST_CASE("closed forms: clipping keeps the side the normal points to") {
    std::vector<DVec3> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    auto left = clipPolygon(square, {1, 0, 0}, {-1, 0, 0});
    REQUIRE(left.size() == 4);
    for (const DVec3& p : left) CHECK(p.x <= 1.0);
    CHECK(clipPolygon(square, {5, 0, 0}, {1, 0, 0}).empty());
    CHECK(clipPolygon(square, {5, 0, 0}, {-1, 0, 0}).size() == 4);
    // The two halves light a point as much as the whole.
    DVec3 x(0.3, 0.7, -1.5), n(0, 0, 1);
    auto right = clipPolygon(square, {1, 0, 0}, {1, 0, 0});
    CHECK(polygonIrradiance(x, n, left) + polygonIrradiance(x, n, right) == doctest::Approx(polygonIrradiance(x, n, square)).epsilon(1e-12));
}

TEST_CASE("closed forms: a fully visible sphere lights like a point source of its power") {
    // L = 1: Phi = 4 pi^2 r^2, I = pi r^2, E = I cos(theta) / d^2.
    DVec3 x(0, 0, 0), centre(1, 3, 0.5);
    double r = 0.4, d = glm::length(centre - x), cosTheta = centre.y / d;
    CHECK(sphereIrradiance(x, {0, 1, 0}, centre, r) == doctest::Approx(kPi * r * r * cosTheta / (d * d)).epsilon(1e-12));
    // Reaching below the horizon, or around the point: no closed form here.
    CHECK(std::isnan(sphereIrradiance(x, {0, 1, 0}, {3, 0.2, 0}, 0.5)));
    CHECK(std::isnan(sphereIrradiance(x, {0, 1, 0}, {0, 0.1, 0}, 0.5)));
}

TEST_CASE("closed forms: Girard's solid angle, the octant and Van Oosterom-Strackee (the a6 reference)") {
    CHECK(triangleSolidAngleByExcess({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == doctest::Approx(kPi / 2).epsilon(1e-14));
    CHECK(solidAngleOfTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == doctest::Approx(kPi / 2).epsilon(1e-14));
    Pcg32 rng(3, 7);
    auto u = [&] { return 4.0 * rng.uniform() - 2.0; };
    for (int i = 0; i < 200; ++i) {
        DVec3 p(u(), u(), u()), a(u(), u(), u()), b(u(), u(), u()), c(u(), u(), u());
        CAPTURE(i);
        CHECK(solidAngleOfTriangle(p, a, b, c) == doctest::Approx(triangleSolidAngleByExcess(p, a, b, c)).epsilon(1e-9));
    }
}
