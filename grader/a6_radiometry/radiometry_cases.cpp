#include "grader/a6_radiometry/radiometry_cases.h"

#include "framework/core/pcg32.h"
#include "framework/oracle/closed_forms.h"
#include "grader/a6_radiometry/sampler_histograms.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace rtlab::grader {
namespace {

using worker::Estimator;
using worker::EstimatorCall;

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
// Three channels of different albedo: a mistake that mixes them up shows.
const Vec3 kAlbedo(0.9f, 0.6f, 0.3f);

// --- Drawing the cases ------------------------------------------------------------------------
// Every case is drawn around its shading point at the origin, with "up" along +z; then the
// whole family (points, lights, occluders) is turned about the vertical by a random angle and
// moved by a random offset, and rounded to float as the worker receives it. The closed forms
// are computed afterwards, from the rounded values, so they are exact for what is graded.

// The uniform numbers of one family of cases, from the grading seed and the estimator.
class Draw {
public:
    Draw(uint64_t seed, Estimator estimator) : rng_(worker::callSeed(seed, 0xa6000u + static_cast<uint64_t>(estimator), 0), 0) {}
    double in(double lo, double hi) { return lo + (hi - lo) * (rng_.next() * 0x1p-32); }
    double angle() { return in(0.0, 2.0 * kPi); }
    // The seed of the uniform numbers the worker draws for one case.
    uint64_t seed() {
        uint64_t high = rng_.next();
        return high << 32 | rng_.next();
    }

private:
    Pcg32 rng_;
};

// Turned about +z by `yaw`, then moved by `offset`: a rigid motion, under which every closed
// form below is invariant.
struct Placement {
    double yaw;
    DVec3 offset;

    DVec3 turn(const DVec3& v) const {
        double c = std::cos(yaw), s = std::sin(yaw);
        return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
    }
    Vec3 point(const DVec3& p) const { return Vec3(turn(p) + offset); }
    Vec3 direction(const DVec3& v) const { return Vec3(glm::normalize(turn(v))); }
};

Placement drawPlacement(Draw& draw) { return {draw.angle(), {draw.in(-2.0, 2.0), draw.in(-2.0, 2.0), draw.in(-2.0, 2.0)}}; }

DVec3 perpendicular(const DVec3& m) { return glm::normalize(glm::cross(m, std::abs(m.x) < 0.9 ? DVec3(1, 0, 0) : DVec3(0, 1, 0))); }

// A unit vector `tilt` away from +z, towards azimuth `azimuth`.
DVec3 tilted(double tilt, double azimuth) { return {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt)}; }

// A normal tilted by 10 to 35 degrees from +z.
DVec3 drawTiltedNormal(Draw& draw) { return tilted(draw.in(10.0, 35.0) * kDegree, draw.angle()); }

// A triangle around `centre` whose front faces `viewer`: its plane turned by up to 25 degrees
// from facing the viewer squarely, its corners a third of a turn apart (+-0.4 rad) at rMin to
// rMax from the centre, counter-clockwise seen from the front.
std::array<DVec3, 3> drawFacingTriangle(Draw& draw, const DVec3& centre, const DVec3& viewer, double rMin, double rMax) {
    DVec3 facing = glm::normalize(viewer - centre), t = perpendicular(facing);
    double tilt = draw.in(0.0, 25.0) * kDegree, around = draw.angle();
    DVec3 m = std::cos(tilt) * facing + std::sin(tilt) * (std::cos(around) * t + std::sin(around) * glm::cross(facing, t));
    DVec3 u1 = perpendicular(m), u2 = glm::cross(m, u1);
    double start = draw.angle();
    std::array<DVec3, 3> corners;
    for (int k = 0; k < 3; ++k) {
        double a = start + k * 2.0 * kPi / 3.0 + draw.in(-0.4, 0.4), r = draw.in(rMin, rMax);
        corners[k] = centre + r * (std::cos(a) * u1 + std::sin(a) * u2);
    }
    return corners;
}

// Whether every corner is at least 5 degrees above the horizon of a point at the origin with
// normal n, so that the closed forms need no clipping at the horizon.
bool aboveHorizon(const std::array<DVec3, 3>& corners, const DVec3& n) {
    for (const DVec3& c : corners)
        if (glm::dot(n, c) < std::sin(5.0 * kDegree) * glm::length(c)) return false;
    return true;
}

bool aboveHorizon(const DVec3& centre, double radius, const DVec3& n) {
    double d = glm::length(centre);
    return std::acos(glm::dot(n, centre) / d) + std::asin(radius / d) <= 85.0 * kDegree;
}

// Draws until `accept` holds (a few tries: the ranges are chosen so that most draws pass).
template <typename Make, typename Accept>
auto drawUntil(Make make, Accept accept) {
    for (int tries = 0; tries < 1000; ++tries)
        if (auto drawn = make(); accept(drawn)) return drawn;
    throw std::logic_error("a6 cases: the ranges leave no room for the constraint");
}

// --- The scene the worker's rays see ----------------------------------------------------------

uint32_t addMaterial(Scene& scene, Vec3 albedo, Vec3 emission, bool doubleSided) {
    scene.materials.push_back(Material{"", albedo, emission, doubleSided});
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

void addTriangle(Scene& scene, const Vec3& p0, const Vec3& p1, const Vec3& p2, uint32_t material) {
    auto base = static_cast<uint32_t>(scene.triangles.positions.size());
    for (const Vec3& p : {p0, p1, p2}) scene.triangles.positions.push_back(p);
    scene.triangles.indices.push_back({base, base + 1, base + 2});
    scene.triangles.material.push_back(material);
    scene.triangles.smooth.push_back(0);
}

void addLight(Scene& scene, const TriangleEmitter& t) {
    addTriangle(scene, t.p0, t.p1, t.p2, addMaterial(scene, Vec3(0.0f), t.radiance, t.twoSided));
}

void addLight(Scene& scene, const SphereEmitter& s) {
    scene.spheres.push_back(Sphere{s.centre, s.radius, addMaterial(scene, Vec3(0.0f), s.radiance, false)});
}

void addOccluder(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c) {
    addTriangle(scene, a, b, c, addMaterial(scene, Vec3(0.5f), Vec3(0.0f), false));
}

// A large grey triangle in the horizontal plane at `height` over everything the lights cover.
void addRoof(Scene& scene, const Placement& place, double height) {
    addOccluder(scene, place.point({-20.0, -20.0, height}), place.point({20.0, -20.0, height}), place.point({0.0, 20.0, height}));
}

EstimatorCall call(Estimator estimator, const ShadingPoint& point, uint32_t count, Draw& draw) {
    EstimatorCall c{};
    c.estimator = estimator;
    c.point = point;
    c.seed = draw.seed();
    c.count = count;
    return c;
}

ShadingPoint shadingPoint(const Placement& place, const DVec3& normal) { return {place.point(DVec3(0.0)), place.direction(normal), kAlbedo}; }

TriangleEmitter triangleLight(const Placement& place, const std::array<DVec3, 3>& corners, double radiance) {
    return {place.point(corners[0]), place.point(corners[1]), place.point(corners[2]), Vec3(float(radiance)), false};
}

SphereEmitter sphereLight(const Placement& place, const DVec3& centre, double radius, double radiance) {
    return {place.point(centre), float(radius), Vec3(float(radiance))};
}

std::string text(const char* format, auto... values) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, format, values...);
    return buffer;
}

std::string describe(const Vec3& v) { return text("(%.6g, %.6g, %.6g)", v.x, v.y, v.z); }

std::string describe(const ShadingPoint& x) { return "x " + describe(x.position) + ", n " + describe(x.normal); }

std::string describe(const TriangleEmitter& t) {
    return "triangle " + describe(t.p0) + " " + describe(t.p1) + " " + describe(t.p2) + (t.twoSided ? " two-sided" : "") +
           text(", L %.6g", t.radiance.x);
}

std::string describe(const SphereEmitter& s) { return "sphere " + describe(s.centre) + text(" r %.6g, L %.6g", s.radius, s.radiance.x); }

// --- Integrals over a light: the mistakes and the spread ----------------------------------------

// An integrand per unit area of the light: g(cos theta_x, cos theta_light, d^2).
using AreaIntegrand = std::function<double(double cosX, double cosLight, double distanceSquared)>;
// The integral of an integrand over the part of a light where samples count.
using Over = std::function<double(const AreaIntegrand&)>;

// Over a flat convex polygon (either side facing x), by the midpoint rule on 64^2 sub-triangles
// of each triangle of its fan.
double overPolygon(const ShadingPoint& x, const std::vector<DVec3>& polygon, const AreaIntegrand& g) {
    double sum = 0.0;
    for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        TriangleBins lattice{polygon[0], polygon[k], polygon[k + 1], 64};
        DVec3 normal = glm::normalize(glm::cross(lattice.p1 - lattice.p0, lattice.p2 - lattice.p0));
        for (const auto& s : lattice.subTriangles()) {
            DVec3 d = (s[0] + s[1] + s[2]) / 3.0 - DVec3(x.position);
            double d2 = glm::dot(d, d);
            DVec3 w = d / std::sqrt(d2);
            double cosX = glm::dot(DVec3(x.normal), w);
            if (cosX > 0.0) sum += g(cosX, std::abs(glm::dot(normal, w)), d2) * 0.5 * glm::length(glm::cross(s[1] - s[0], s[2] - s[0]));
        }
    }
    return sum;
}

// Over the cap of the sphere that faces x (the points whose outward normal m has
// m . (x - centre) / |x - centre| > r / |x - centre|), by the midpoint rule in (that cosine, phi).
double overSphere(const ShadingPoint& x, const SphereEmitter& light, const AreaIntegrand& g) {
    DVec3 centre(light.centre), axis = DVec3(x.position) - centre;
    double r = light.radius, D = glm::length(axis);
    DVec3 u = axis / D, t1 = perpendicular(u), t2 = glm::cross(u, t1);
    const int steps = 256;
    double muMin = r / D, dMu = (1.0 - muMin) / steps, dPhi = 2.0 * kPi / steps, sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        double mu = muMin + (i + 0.5) * dMu, s = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < steps; ++j) {
            double phi = (j + 0.5) * dPhi;
            DVec3 m = mu * u + s * (std::cos(phi) * t1 + std::sin(phi) * t2);
            DVec3 d = centre + r * m - DVec3(x.position);
            double d2 = glm::dot(d, d);
            DVec3 w = d / std::sqrt(d2);
            double cosX = glm::dot(DVec3(x.normal), w);
            if (cosX > 0.0) sum += g(cosX, -glm::dot(m, w), d2) * r * r * dMu * dPhi;
        }
    }
    return sum;
}

std::vector<DVec3> corners(const TriangleEmitter& t) { return {DVec3(t.p0), DVec3(t.p1), DVec3(t.p2)}; }

double area(const std::vector<DVec3>& polygon) {
    DVec3 sum(0.0);
    for (size_t k = 1; k + 1 < polygon.size(); ++k) sum += glm::cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]);
    return 0.5 * glm::length(sum);
}

double solidAngle(const ShadingPoint& x, const std::vector<DVec3>& polygon) {
    double sum = 0.0;
    for (size_t k = 1; k + 1 < polygon.size(); ++k) sum += triangleSolidAngleByExcess(DVec3(x.position), polygon[0], polygon[k], polygon[k + 1]);
    return sum;
}

// A sphere's solid angle seen from x: 2 pi (1 - cos alpha), written without cancellation.
double solidAngle(const ShadingPoint& x, const SphereEmitter& s) {
    double d = glm::length(DVec3(s.centre) - DVec3(x.position)), sin2 = double(s.radius) * s.radius / (d * d);
    return 2.0 * kPi * sin2 / (1.0 + std::sqrt(1.0 - sin2));
}

// Radiance 1: the integral of cos(theta_x) dOmega over what x sees of a light.
double irradiance(const ShadingPoint& x, const std::vector<DVec3>& visible) { return polygonIrradiance(DVec3(x.position), DVec3(x.normal), visible); }
double irradiance(const ShadingPoint& x, const SphereEmitter& s) {
    return sphereIrradiance(DVec3(x.position), DVec3(x.normal), DVec3(s.centre), s.radius);
}

// Per channel, albedo / pi times a radiance: the factor every sample and integral below takes.
DVec3 brdfTimes(double radiance) { return DVec3(kAlbedo) * radiance / kPi; }

// How an estimator draws the light point y a sample stands for, both per unit of the light's
// area: the density of y, and the sample there without the factor albedo L / pi. E.g. area
// sampling of a triangle of area A: density 1 / A, sample cos(theta_x) cos(theta_light) A / d^2.
struct SamplingRule {
    AreaIntegrand density;
    AreaIntegrand value;
};

SamplingRule byArea(double area) {
    return {[area](double, double, double) { return 1.0 / area; },
            [area](double cosX, double cosLight, double d2) { return cosX * cosLight * area / d2; }};
}

SamplingRule bySolidAngle(double omega) {
    return {[omega](double, double cosLight, double d2) { return cosLight / (d2 * omega); },
            [omega](double cosX, double, double) { return cosX * omega; }};
}

// The spread of a sample X = factor * value(y) about its mean factor * mean, with y drawn by
// `rule`: the integral over the part of the light where samples count (`over`), which a sample
// lands on with probability `reach`, plus X = 0 everywhere else.
Spread spreadOf(const DVec3& factor, double mean, double reach, const SamplingRule& rule, const Over& over) {
    auto central = [&](int k) {
        double counted = over([&](double cosX, double cosLight, double d2) {
            return std::pow(rule.value(cosX, cosLight, d2) - mean, k) * rule.density(cosX, cosLight, d2);
        });
        return counted + std::pow(-mean, k) * (1.0 - reach);
    };
    DVec3 f2 = factor * factor;
    return {f2 * central(2), f2 * f2 * central(4)};
}

// What the common mistakes give for an unoccluded light (docs/a6-radiometry.md#common-mistakes).
std::vector<Mistake> lightMistakes(const DVec3& expected, const DVec3& factor, const Over& over, bool sampledByArea, bool sphere = false) {
    std::vector<Mistake> m{{"the 1/pi of Lambert's BRDF is missing", kPi * expected},
                           {"cos(theta_x) at the shading point is missing", factor * over([](double, double cosLight, double d2) { return cosLight / d2; })}};
    if (sampledByArea) {
        m.push_back({"the light's cos(theta_light) is missing from the change of density",
                     factor * over([](double cosX, double, double d2) { return cosX / d2; })});
        m.push_back({"the 1/d^2 is missing from the change of density", factor * over([](double cosX, double cosLight, double) { return cosX * cosLight; })});
        m.push_back({"the density per unit area is used as a density per steradian (no areaToSolidAnglePdf)",
                     factor * over([](double cosX, double, double) { return cosX; })});
        if (sphere) m.push_back({"the density of points on the whole sphere taken as the visible half's, 1/(2 pi r^2)", 0.5 * expected});
    }
    return m;
}

bool sampledByArea(Estimator e) { return e == Estimator::TriangleByArea || e == Estimator::SphereByArea; }

}  // namespace

std::vector<EstimatorCase> pointLightCases(uint64_t seed) {
    Draw draw(seed, Estimator::PointLight);
    Placement place = drawPlacement(draw);
    ShadingPoint x = shadingPoint(place, {0, 0, 1});
    std::vector<EstimatorCase> cases;
    // The exact answer is albedo / pi * I cos(theta) / d^2; each light's intensity (grey) in [2, 8] W/sr.
    auto add = [&](std::string id, const DVec3& local, double roof) {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(Estimator::PointLight, x, 1, draw);
        c.call.pointLight = {place.point(local), Vec3(float(draw.in(2.0, 8.0)))};
        if (roof > 0.0) addRoof(c.scene, place, roof);
        c.inputs = describe(x) + ", light " + describe(c.call.pointLight.position) + text(", I %.6g", c.call.pointLight.intensity.x);
        DVec3 toLight = DVec3(c.call.pointLight.position) - DVec3(x.position);
        double d2 = glm::dot(toLight, toLight), cosTheta = glm::dot(DVec3(x.normal), toLight) / std::sqrt(d2);
        DVec3 factor = DVec3(kAlbedo) * double(c.call.pointLight.intensity.x) / kPi, lit = factor * cosTheta / d2;
        if (cosTheta <= 0.0) {
            c.expected = DVec3(0.0);
            c.mistakes = {{"light from below the horizon counted (cos(theta_x) < 0 not checked)", lit}};
        } else if (roof > 0.0) {
            c.expected = DVec3(0.0);
            c.mistakes = {{"the shadow ray is not cast, or its answer ignored", lit}};
        } else {
            c.expected = lit;
            c.mistakes = {{"the 1/pi of Lambert's BRDF is missing", kPi * lit},
                          {"cos(theta_x) at the shading point is missing", factor / d2},
                          {"the 1/d^2 is missing", factor * cosTheta},
                          {"1/d instead of 1/d^2", factor * cosTheta / std::sqrt(d2)}};
        }
        cases.push_back(std::move(c));
    };
    DVec3 above(draw.in(-0.6, 0.6), draw.in(-0.6, 0.6), draw.in(1.5, 2.5));
    add("P1 a light above the point", above, 0.0);
    double low = draw.in(8.0, 20.0) * kDegree, lowAzimuth = draw.angle(), lowDistance = draw.in(1.5, 2.5);
    add("P2 a light low over the horizon", lowDistance * DVec3(std::cos(low) * std::cos(lowAzimuth), std::cos(low) * std::sin(lowAzimuth), std::sin(low)), 0.0);
    double below = draw.in(15.0, 60.0) * kDegree, belowAzimuth = draw.angle(), belowDistance = draw.in(1.0, 2.0);
    add("P3 a light below the horizon",
        belowDistance * DVec3(std::cos(below) * std::cos(belowAzimuth), std::cos(below) * std::sin(belowAzimuth), -std::sin(below)), 0.0);
    add("P4 the light of P1 behind an occluder", above, draw.in(0.3, 0.7) * above.z);
    return cases;
}

std::vector<EstimatorCase> triangleLightCases(Estimator estimator, uint64_t seed) {
    Draw draw(seed, estimator);
    Placement place = drawPlacement(draw);
    std::vector<EstimatorCase> cases;
    // One case: the exact answer by Lambert's contour formula over the part of the light x sees
    // (from its front, or either side when two-sided), and the spread of the estimator's samples.
    auto add = [&](std::string id, const ShadingPoint& x, const TriangleEmitter& light, const std::vector<DVec3>& visible,
                   std::vector<Mistake> mistakes = {}) -> EstimatorCase& {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(estimator, x, kLightSamplesPerCase, draw);
        c.call.triangle = light;
        addLight(c.scene, light);
        c.inputs = describe(x) + ", " + describe(light);
        DVec3 factor = brdfTimes(light.radiance.x);
        double mean = visible.empty() ? 0.0 : irradiance(x, visible);
        c.expected = factor * mean;
        if (!visible.empty()) {
            std::vector<DVec3> whole = corners(light);
            auto over = [&](const AreaIntegrand& g) { return overPolygon(x, visible, g); };
            c.spread = sampledByArea(estimator) ? spreadOf(factor, mean, area(visible) / area(whole), byArea(area(whole)), over)
                                                : spreadOf(factor, mean, solidAngle(x, visible) / solidAngle(x, whole),
                                                           bySolidAngle(solidAngle(x, whole)), over);
            if (mistakes.empty()) mistakes = lightMistakes(c.expected, factor, over, sampledByArea(estimator));
        }
        c.mistakes = std::move(mistakes);
        cases.push_back(std::move(c));
        return cases.back();
    };
    double radiance = draw.in(1.0, 4.0);
    ShadingPoint up = shadingPoint(place, {0, 0, 1});
    std::array<DVec3, 3> local = drawFacingTriangle(draw, {draw.in(-0.4, 0.4), draw.in(-0.4, 0.4), draw.in(1.0, 1.6)}, DVec3(0.0), 0.35, 0.7);
    TriangleEmitter front = triangleLight(place, local, radiance);
    DVec3 lit = add("T1 a triangle facing the point", up, front, corners(front)).expected;

    // A normal tilted by 10 to 35 degrees, the light 1.2 to 2 m to a side, 0.8 to 1.6 m up.
    auto [normal, side] = drawUntil(
        [&] {
            DVec3 n = drawTiltedNormal(draw);
            double azimuth = draw.angle(), distance = draw.in(1.2, 2.0);
            DVec3 centre(distance * std::cos(azimuth), distance * std::sin(azimuth), draw.in(0.8, 1.6));
            return std::make_pair(n, drawFacingTriangle(draw, centre, DVec3(0.0), 0.3, 0.6));
        },
        [](const auto& drawn) { return aboveHorizon(drawn.second, drawn.first); });
    TriangleEmitter sideLight = triangleLight(place, side, radiance);
    add("T2 a tilted point, the light to its side", shadingPoint(place, normal), sideLight, corners(sideLight));

    TriangleEmitter back = front;
    std::swap(back.p1, back.p2);  // the same triangle, its front turned away from the point
    add("T3 the back of a one-sided triangle", up, back, {}, {{"the back of a one-sided light emits", lit}});
    back.twoSided = true;
    add("T4 the back of a two-sided triangle", up, back, corners(back), {{"a two-sided light emits only from its front", DVec3(0.0)}});

    // An occluder at 0.4 to 0.6 of the light's lowest corner, its edge across the light: the
    // plane through x and the edge leaves 20 to 80 % of the light's solid angle in sight.
    double lowest = std::min({local[0].z, local[1].z, local[2].z}), height = draw.in(0.4, 0.6) * lowest;
    DVec3 centroid = (local[0] + local[1] + local[2]) / 3.0;
    struct Edge {
        DVec3 along, through, visibleSide;
    };
    std::vector<DVec3> frontCorners = corners(front);
    Edge edge = drawUntil(
        [&] {
            double turn = draw.angle();
            DVec3 along(std::cos(turn), std::sin(turn), 0.0), across(-along.y, along.x, 0.0);
            DVec3 through = centroid + draw.in(-0.15, 0.15) * across;
            DVec3 plane = glm::normalize(glm::cross(along, through));
            return Edge{along, through, draw.in(0.0, 1.0) < 0.5 ? plane : -plane};
        },
        [&](const Edge& e) {
            std::vector<DVec3> visible = clipPolygon(frontCorners, DVec3(up.position), place.turn(e.visibleSide));
            double share = visible.size() < 3 ? 0.0 : solidAngle(up, visible) / solidAngle(up, frontCorners);
            return share > 0.2 && share < 0.8;
        });
    DVec3 onEdge = edge.through * (height / edge.through.z), away(-edge.along.y, edge.along.x, 0.0);
    if (glm::dot(away, edge.visibleSide) > 0.0) away = -away;
    // The visible part is cut by the plane through x and the occluder's edge as the worker gets
    // them, in float.
    Vec3 edge0 = place.point(onEdge - 20.0 * edge.along), edge1 = place.point(onEdge + 20.0 * edge.along);
    DVec3 cut = glm::normalize(glm::cross(DVec3(edge0) - DVec3(up.position), DVec3(edge1) - DVec3(up.position)));
    if (glm::dot(cut, place.turn(edge.visibleSide)) < 0.0) cut = -cut;
    EstimatorCase& t5 = add("T5 an edge of an occluder across the light", up, front, clipPolygon(frontCorners, DVec3(up.position), cut),
                            {{"the shadow ray is not cast, or its answer ignored", lit}});
    addOccluder(t5.scene, edge0, edge1, place.point(onEdge + 20.0 * away));

    EstimatorCase& t6 = add("T6 the light behind an occluder", up, front, {}, {{"the shadow ray is not cast, or its answer ignored", lit}});
    addRoof(t6.scene, place, draw.in(0.4, 0.6) * lowest);
    return cases;
}

std::vector<EstimatorCase> sphereLightCases(Estimator estimator, uint64_t seed) {
    Draw draw(seed, estimator);
    Placement place = drawPlacement(draw);
    std::vector<EstimatorCase> cases;
    auto add = [&](std::string id, const ShadingPoint& x, const SphereEmitter& light, bool lit) -> EstimatorCase& {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(estimator, x, kLightSamplesPerCase, draw);
        c.call.sphere = light;
        addLight(c.scene, light);
        c.inputs = describe(x) + ", " + describe(light);
        DVec3 factor = brdfTimes(light.radiance.x);
        if (lit) {
            // pi L sin^2(alpha) cos(theta), the sphere wholly above the horizon.
            double mean = irradiance(x, light), r = light.radius, d = glm::length(DVec3(light.centre) - DVec3(x.position));
            c.expected = factor * mean;
            auto over = [&](const AreaIntegrand& g) { return overSphere(x, light, g); };
            // Area sampling draws the whole sphere, whose cap seen from x holds (1 - r/d) / 2 of
            // its area; the cone holds nothing else.
            c.spread = sampledByArea(estimator) ? spreadOf(factor, mean, 0.5 * (1.0 - r / d), byArea(4.0 * kPi * r * r), over)
                                                : spreadOf(factor, mean, 1.0, bySolidAngle(solidAngle(x, light)), over);
            c.mistakes = lightMistakes(c.expected, factor, over, sampledByArea(estimator), true);
        }
        cases.push_back(std::move(c));
        return cases.back();
    };
    double radiance = draw.in(1.0, 4.0);
    ShadingPoint up = shadingPoint(place, {0, 0, 1});
    DVec3 centre{draw.in(-0.5, 0.5), draw.in(-0.5, 0.5), draw.in(1.1, 2.0)};
    double radius = draw.in(0.2, 0.5);
    SphereEmitter above = sphereLight(place, centre, radius, radiance);
    DVec3 lit = add("S1 a sphere above the point", up, above, true).expected;

    // A normal tilted by 10 to 35 degrees, the sphere 1.2 to 2 m to a side, 0.8 to 1.6 m up.
    struct Side {
        DVec3 normal, centre;
        double radius;
    };
    Side side = drawUntil(
        [&] {
            DVec3 n = drawTiltedNormal(draw);
            double azimuth = draw.angle(), distance = draw.in(1.2, 2.0);
            DVec3 c{distance * std::cos(azimuth), distance * std::sin(azimuth), draw.in(0.8, 1.6)};
            return Side{n, c, draw.in(0.25, 0.5)};
        },
        [](const Side& s) { return aboveHorizon(s.centre, s.radius, s.normal); });
    add("S2 a tilted point, the sphere to its side", shadingPoint(place, side.normal), sphereLight(place, side.centre, side.radius, radiance), true);

    EstimatorCase& s3 = add("S3 the sphere of S1 behind an occluder", up, above, false);
    s3.mistakes = {{"the shadow ray is not cast, or its answer ignored", lit}};
    addRoof(s3.scene, place, draw.in(0.3, 0.7) * (centre.z - radius));

    // The centre within half the radius of the point.
    double inner = draw.in(0.3, 0.8), shift = draw.in(0.0, 0.5) * inner, polar = std::acos(draw.in(-1.0, 1.0)), azimuth = draw.angle();
    DVec3 offset = shift * tilted(polar, azimuth);
    add("S4 the point inside the sphere", up, sphereLight(place, offset, inner, radiance), false);
    return cases;
}

std::vector<EstimatorCase> directionCases(Estimator estimator, uint64_t seed) {
    Draw draw(seed, estimator);
    Placement place = drawPlacement(draw);
    std::vector<EstimatorCase> cases;
    bool cosine = estimator == Estimator::CosineHemisphere;
    // The triangle lies where local y < 0, the sphere where y > 0: seen from x they never
    // overlap, so the answer is the sum of the two closed forms.
    struct Layout {
        DVec3 normal;
        std::array<DVec3, 3> triangle;
        DVec3 centre;
        double radius;
    };
    auto add = [&](std::string id, const Layout& l) {
        double radiance = draw.in(1.0, 4.0);
        ShadingPoint x = shadingPoint(place, l.normal);
        TriangleEmitter t = triangleLight(place, l.triangle, radiance);
        SphereEmitter s = sphereLight(place, l.centre, l.radius, radiance);
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(estimator, x, kDirectionSamplesPerCase, draw);
        addLight(c.scene, t);
        addLight(c.scene, s);
        c.inputs = describe(x) + ", " + describe(t) + ", " + describe(s);
        DVec3 factor = brdfTimes(radiance);
        double mean = irradiance(x, corners(t)) + irradiance(x, s);
        c.expected = factor * mean;
        auto both = [&](const AreaIntegrand& g) { return overPolygon(x, corners(t), g) + overSphere(x, s, g); };
        // A direction about the normal finds a light with probability Omega / (2 pi) (uniform)
        // or E / pi (cosine-weighted, E the light's irradiance at radiance 1).
        SamplingRule uniform{[](double, double cosLight, double d2) { return cosLight / (2.0 * kPi * d2); },
                             [](double cosX, double, double) { return 2.0 * kPi * cosX; }};
        SamplingRule weighted{[](double cosX, double cosLight, double d2) { return cosX * cosLight / (kPi * d2); },
                              [](double, double, double) { return kPi; }};
        c.spread = cosine ? spreadOf(factor, mean, mean / kPi, weighted, both)
                          : spreadOf(factor, mean, (solidAngle(x, corners(t)) + solidAngle(x, s)) / (2.0 * kPi), uniform, both);
        c.mistakes = lightMistakes(c.expected, factor, both, false);
        // Cosine-weighted directions divided by the uniform density 1 / (2 pi): each sample
        // weighs 2 pi cos / pi times too much where it lands, 2 cos^2 in all.
        if (cosine)
            c.mistakes.push_back({"the pdf is the uniform hemisphere's 1/(2 pi), not cos(theta)/pi",
                                  factor * both([](double cosX, double cosLight, double d2) { return 2.0 * cosX * cosX * cosLight / d2; })});
        cases.push_back(std::move(c));
    };
    auto triangleAt = [&](double xLo, double xHi, double yLo, double yHi, double zLo, double zHi, double rMax) {
        return drawFacingTriangle(draw, {draw.in(xLo, xHi), draw.in(yLo, yHi), draw.in(zLo, zHi)}, DVec3(0.0), 0.3, rMax);
    };
    auto centreAt = [&](double xLo, double xHi, double yLo, double yHi, double zLo, double zHi) {
        return DVec3{draw.in(xLo, xHi), draw.in(yLo, yHi), draw.in(zLo, zHi)};
    };

    // Each layout: the normal, then the triangle and the sphere within their ranges, drawn
    // again until both are wholly above the horizon.
    auto layout = [&](const std::function<Layout()>& make) {
        return drawUntil(make, [](const Layout& l) { return aboveHorizon(l.triangle, l.normal) && aboveHorizon(l.centre, l.radius, l.normal); });
    };
    add("D1 a triangle and a sphere light above the point", layout([&] {
            std::array<DVec3, 3> t = triangleAt(-0.5, 0.5, -1.2, -0.7, 1.0, 1.5, 0.5);
            DVec3 c = centreAt(-0.5, 0.5, 0.7, 1.3, 0.9, 1.5);
            return Layout{{0, 0, 1}, t, c, draw.in(0.2, 0.4)};
        }));
    add("D2 a tilted point, the lights to its sides", layout([&] {
            DVec3 n = drawTiltedNormal(draw);
            std::array<DVec3, 3> t = triangleAt(-0.6, 0.6, -1.8, -1.0, 0.8, 1.4, 0.5);
            DVec3 c = centreAt(-0.6, 0.6, 1.0, 1.8, 0.8, 1.4);
            return Layout{n, t, c, draw.in(0.25, 0.45)};
        }));
    // A point on a wall: the lights in front of it reach below its height, where directions
    // about +z that were never turned to the normal do not go.
    add("D3 a point on a wall (normal horizontal), lights in front of it reaching below its height", layout([&] {
            std::array<DVec3, 3> t = triangleAt(0.9, 1.5, -1.1, -0.65, -0.9, -0.3, 0.5);
            DVec3 c = centreAt(1.0, 1.6, 0.7, 1.3, -1.0, -0.4);
            return Layout{{1, 0, 0}, t, c, draw.in(0.2, 0.35)};
        }));
    return cases;
}

}  // namespace rtlab::grader
