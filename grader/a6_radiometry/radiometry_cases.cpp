#include "grader/a6_radiometry/radiometry_cases.h"

#include "framework/oracle/closed_forms.h"
#include "grader/a6_radiometry/sampler_histograms.h"

#include <cmath>
#include <functional>
#include <numbers>

namespace rtlab::grader {
namespace {

using worker::Estimator;
using worker::EstimatorCall;

constexpr double kPi = std::numbers::pi;
// Three channels of different albedo: a mistake that mixes them up shows.
const Vec3 kAlbedo(0.9f, 0.6f, 0.3f);
const Vec3 kRadiance(2.0f);
const Vec3 kUp(0.0f, 0.0f, 1.0f);

// Per channel, albedo / pi times the emitted radiance: the factor every integral below takes.
DVec3 brdfTimes(const Vec3& radiance) { return DVec3(kAlbedo) * DVec3(radiance) / kPi; }

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

// A large grey triangle in the plane z = height over the region the lights cover (a 40 m wide
// base along y = yEdge, its apex at y = 20): with yEdge = -20 it hides everything above.
void addOccluder(Scene& scene, float height, float yEdge) {
    addTriangle(scene, {-20.0f, yEdge, height}, {20.0f, yEdge, height}, {0.0f, 20.0f, height},
                addMaterial(scene, Vec3(0.5f), Vec3(0.0f), false));
}

ShadingPoint at(const Vec3& position, const Vec3& normal) { return {position, glm::normalize(normal), kAlbedo}; }

EstimatorCall call(Estimator estimator, const ShadingPoint& point, uint32_t count) {
    EstimatorCall c{};
    c.estimator = estimator;
    c.point = point;
    c.seed = 0x5eed0000u + static_cast<uint32_t>(estimator);
    c.count = count;
    return c;
}

// --- Integrals over a light, for the mistakes ------------------------------------------------

// An integrand per unit area of the light: g(cos theta_x, cos theta_light, d^2).
using AreaIntegrand = std::function<double(double cosX, double cosLight, double distanceSquared)>;

// Over the triangle's side facing x (either side), by the midpoint rule on 64^2 sub-triangles.
double overTriangle(const ShadingPoint& x, const TriangleEmitter& light, const AreaIntegrand& g) {
    TriangleBins lattice{DVec3(light.p0), DVec3(light.p1), DVec3(light.p2), 64};
    DVec3 normal = glm::normalize(glm::cross(lattice.p1 - lattice.p0, lattice.p2 - lattice.p0));
    double sum = 0.0;
    for (const auto& s : lattice.subTriangles()) {
        DVec3 d = (s[0] + s[1] + s[2]) / 3.0 - DVec3(x.position);
        double d2 = glm::dot(d, d);
        DVec3 w = d / std::sqrt(d2);
        double cosX = glm::dot(DVec3(x.normal), w);
        if (cosX > 0.0) sum += g(cosX, std::abs(glm::dot(normal, w)), d2) * 0.5 * glm::length(glm::cross(s[1] - s[0], s[2] - s[0]));
    }
    return sum;
}

// Over the cap of the sphere that faces x (the points whose outward normal m has
// m . (x - centre) / |x - centre| > r / |x - centre|), by the midpoint rule in (that cosine, phi).
double overSphere(const ShadingPoint& x, const SphereEmitter& light, const AreaIntegrand& g) {
    DVec3 centre(light.centre), axis = DVec3(x.position) - centre;
    double r = light.radius, D = glm::length(axis);
    DVec3 u = axis / D;
    DVec3 t1 = glm::normalize(glm::cross(u, std::abs(u.x) < 0.9 ? DVec3(1, 0, 0) : DVec3(0, 1, 0))), t2 = glm::cross(u, t1);
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

// What the common mistakes give for an unoccluded light (docs/a6-radiometry.md#common-mistakes).
std::vector<Mistake> lightMistakes(const DVec3& expected, const DVec3& factor, const std::function<double(const AreaIntegrand&)>& over,
                                   bool byArea, bool sphere = false) {
    std::vector<Mistake> m{{"the 1/pi of Lambert's BRDF is missing", kPi * expected},
                           {"cos(theta_x) at the shading point is missing", factor * over([](double, double cosLight, double d2) { return cosLight / d2; })}};
    if (byArea) {
        m.push_back({"the light's cos(theta_light) is missing from the change of density",
                     factor * over([](double cosX, double, double d2) { return cosX / d2; })});
        m.push_back({"the 1/d^2 is missing from the change of density", factor * over([](double cosX, double cosLight, double) { return cosX * cosLight; })});
        m.push_back({"the density per unit area is used as a density per steradian (no areaToSolidAnglePdf)",
                     factor * over([](double cosX, double, double) { return cosX; })});
        if (sphere) m.push_back({"the density of points on the whole sphere taken as the visible half's, 1/(2 pi r^2)", 0.5 * expected});
    }
    return m;
}

bool byArea(Estimator e) { return e == Estimator::TriangleByArea || e == Estimator::SphereByArea; }

// The light a triangle case uses: its front side (p1 - p0) x (p2 - p0) faces the point below.
TriangleEmitter facingLight() { return {{-0.5f, -0.4f, 1.0f}, {0.1f, 0.7f, 0.9f}, {0.6f, -0.3f, 1.2f}, kRadiance, false}; }

// The exact mean: Lambert's contour formula over the part of the light the point sees.
DVec3 triangleExpected(const ShadingPoint& x, const TriangleEmitter& t, const std::vector<DVec3>& visible) {
    return brdfTimes(t.radiance) * polygonIrradiance(DVec3(x.position), DVec3(x.normal), visible);
}

std::vector<DVec3> corners(const TriangleEmitter& t) { return {DVec3(t.p0), DVec3(t.p1), DVec3(t.p2)}; }

}  // namespace

std::vector<EstimatorCase> pointLightCases() {
    std::vector<EstimatorCase> cases;
    const Vec3 intensity(4.0f);
    DVec3 factor = DVec3(kAlbedo) * DVec3(intensity) / kPi;
    // expected(p) = albedo / pi * I cos / d^2 from the origin with normal +z.
    auto add = [&](std::string id, Vec3 position, bool occluded, DVec3 expected, std::vector<Mistake> mistakes) {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(Estimator::PointLight, at(Vec3(0.0f), kUp), 1);
        c.call.pointLight = {position, intensity};
        if (occluded) addOccluder(c.scene, 1.0f, -20.0f);
        c.expected = expected;
        c.mistakes = std::move(mistakes);
        cases.push_back(std::move(c));
    };
    auto forLight = [&](Vec3 p, bool occluded) {
        double d2 = glm::dot(DVec3(p), DVec3(p)), cosTheta = p.z / std::sqrt(d2);
        DVec3 lit = factor * cosTheta / d2;
        std::vector<Mistake> m{{"the 1/pi of Lambert's BRDF is missing", kPi * lit},
                               {"cos(theta_x) at the shading point is missing", factor / d2},
                               {"the 1/d^2 is missing", factor * cosTheta},
                               {"1/d instead of 1/d^2", factor * cosTheta / std::sqrt(d2)}};
        if (occluded) m = {{"the shadow ray is not cast, or its answer ignored", lit}};
        return std::make_pair(occluded ? DVec3(0.0) : lit, m);
    };
    auto [p1, m1] = forLight({0.3f, -0.4f, 2.0f}, false);
    add("P1 a light above the point (d^2 = 4.25)", {0.3f, -0.4f, 2.0f}, false, p1, m1);
    auto [p2, m2] = forLight({2.0f, 1.0f, 0.5f}, false);
    add("P2 a light low over the horizon (cos(theta) = 0.218)", {2.0f, 1.0f, 0.5f}, false, p2, m2);
    add("P3 a light below the horizon", {0.5f, 0.0f, -1.0f}, false, DVec3(0.0),
        {{"light from below the horizon counted (cos(theta_x) < 0 not checked)",
          factor * (-1.0 / std::sqrt(1.25)) / 1.25}});
    auto [p4, m4] = forLight({0.3f, -0.4f, 2.0f}, true);
    add("P4 the light of P1 behind an occluder", {0.3f, -0.4f, 2.0f}, true, p4, m4);
    return cases;
}

std::vector<EstimatorCase> triangleLightCases(Estimator estimator) {
    std::vector<EstimatorCase> cases;
    auto make = [&](std::string id, const ShadingPoint& x, const TriangleEmitter& light) {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(estimator, x, kLightSamplesPerCase);
        c.call.triangle = light;
        addLight(c.scene, light);
        return c;
    };
    auto unoccluded = [&](const ShadingPoint& x, const TriangleEmitter& light) {
        DVec3 expected = triangleExpected(x, light, corners(light));
        auto over = [&](const AreaIntegrand& g) { return overTriangle(x, light, g); };
        return std::make_pair(expected, lightMistakes(expected, brdfTimes(light.radiance), over, byArea(estimator)));
    };
    ShadingPoint below = at(Vec3(0.0f), kUp);
    TriangleEmitter front = facingLight();
    auto [value, mistakes] = unoccluded(below, front);

    EstimatorCase t1 = make("T1 a triangle facing the point", below, front);
    t1.expected = value;
    t1.mistakes = mistakes;
    cases.push_back(t1);

    ShadingPoint tilted = at({0.3f, -0.2f, 0.0f}, {0.3f, 0.1f, 1.0f});
    TriangleEmitter side{{1.5f, 0.2f, 0.8f}, {1.4f, 1.1f, 1.9f}, {2.2f, 0.9f, 1.6f}, kRadiance, false};
    EstimatorCase t2 = make("T2 a tilted point, the light to its side", tilted, side);
    std::tie(t2.expected, t2.mistakes) = unoccluded(tilted, side);
    cases.push_back(t2);

    TriangleEmitter back = front;
    std::swap(back.p1, back.p2);  // the same triangle, its front turned away from the point
    EstimatorCase t3 = make("T3 the back of a one-sided triangle", below, back);
    t3.expected = DVec3(0.0);
    t3.mistakes = {{"the back of a one-sided light emits", value}};
    cases.push_back(t3);

    back.twoSided = true;
    EstimatorCase t4 = make("T4 the back of a two-sided triangle", below, back);
    t4.expected = value;
    t4.mistakes = {{"a two-sided light emits only from its front", DVec3(0.0)}};
    cases.push_back(t4);

    // An occluder at z = 0.5 over y > 0.1 hides the part of the light beyond the plane through
    // the point and the occluder's edge (the points q with 0.5 q.y < 0.1 q.z stay visible).
    EstimatorCase t5 = make("T5 an edge of an occluder across the light", below, front);
    addOccluder(t5.scene, 0.5f, 0.1f);
    t5.expected = triangleExpected(below, front, clipPolygon(corners(front), DVec3(0.0), DVec3(0.0, -0.5, 0.1)));
    t5.mistakes = {{"the shadow ray is not cast, or its answer ignored", value}};
    cases.push_back(t5);

    EstimatorCase t6 = make("T6 the light behind an occluder", below, front);
    addOccluder(t6.scene, 0.5f, -20.0f);
    t6.expected = DVec3(0.0);
    t6.mistakes = {{"the shadow ray is not cast, or its answer ignored", value}};
    cases.push_back(t6);
    return cases;
}

std::vector<EstimatorCase> sphereLightCases(Estimator estimator) {
    std::vector<EstimatorCase> cases;
    auto make = [&](std::string id, const ShadingPoint& x, const SphereEmitter& light, DVec3 expected, std::vector<Mistake> mistakes) {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(estimator, x, kLightSamplesPerCase);
        c.call.sphere = light;
        addLight(c.scene, light);
        c.expected = expected;
        c.mistakes = std::move(mistakes);
        return c;
    };
    auto unoccluded = [&](const ShadingPoint& x, const SphereEmitter& light) {
        DVec3 expected =
            brdfTimes(light.radiance) * sphereIrradiance(DVec3(x.position), DVec3(x.normal), DVec3(light.centre), light.radius);
        auto over = [&](const AreaIntegrand& g) { return overSphere(x, light, g); };
        return std::make_pair(expected, lightMistakes(expected, brdfTimes(light.radiance), over, byArea(estimator), true));
    };
    ShadingPoint below = at(Vec3(0.0f), kUp);
    SphereEmitter above{{0.2f, -0.1f, 1.5f}, 0.4f, kRadiance};
    auto [value, mistakes] = unoccluded(below, above);
    cases.push_back(make("S1 a sphere above the point", below, above, value, mistakes));

    ShadingPoint tilted = at(Vec3(0.0f), {-0.2f, 0.1f, 1.0f});
    SphereEmitter side{{1.5f, 0.8f, 1.2f}, 0.5f, kRadiance};
    auto [sideValue, sideMistakes] = unoccluded(tilted, side);
    cases.push_back(make("S2 a tilted point, the sphere to its side", tilted, side, sideValue, sideMistakes));

    EstimatorCase s3 = make("S3 the sphere of S1 behind an occluder", below, above, DVec3(0.0),
                            {{"the shadow ray is not cast, or its answer ignored", value}});
    addOccluder(s3.scene, 0.6f, -20.0f);
    cases.push_back(s3);

    SphereEmitter around{{0.0f, 0.0f, 0.1f}, 0.5f, kRadiance};
    cases.push_back(make("S4 the point inside the sphere", below, around, DVec3(0.0), {}));
    return cases;
}

std::vector<EstimatorCase> directionCases(Estimator estimator) {
    std::vector<EstimatorCase> cases;
    bool cosine = estimator == Estimator::CosineHemisphere;
    auto make = [&](std::string id, const ShadingPoint& x, const TriangleEmitter& triangle, const SphereEmitter& sphere) {
        EstimatorCase c;
        c.id = std::move(id);
        c.call = call(estimator, x, kDirectionSamplesPerCase);
        addLight(c.scene, triangle);
        addLight(c.scene, sphere);
        DVec3 factor = brdfTimes(kRadiance);
        auto both = [&](const AreaIntegrand& g) { return overTriangle(x, triangle, g) + overSphere(x, sphere, g); };
        c.expected = triangleExpected(x, triangle, corners(triangle)) +
                     factor * sphereIrradiance(DVec3(x.position), DVec3(x.normal), DVec3(sphere.centre), sphere.radius);
        c.mistakes = lightMistakes(c.expected, factor, both, false);
        // Cosine-weighted directions divided by the uniform density 1 / (2 pi): each sample
        // weighs 2 pi cos / pi times too much where it lands, 2 cos^2 in all.
        if (cosine)
            c.mistakes.push_back({"the pdf is the uniform hemisphere's 1/(2 pi), not cos(theta)/pi",
                                  factor * both([](double cosX, double cosLight, double d2) { return 2.0 * cosX * cosX * cosLight / d2; })});
        cases.push_back(std::move(c));
    };
    make("D1 a triangle and a sphere light above the point", at(Vec3(0.0f), kUp), facingLight(),
         SphereEmitter{{2.0f, 1.0f, 1.2f}, 0.5f, kRadiance});
    make("D2 a tilted point, both lights to its side", at({0.3f, -0.2f, 0.0f}, {0.3f, 0.1f, 1.0f}),
         TriangleEmitter{{1.5f, 0.2f, 0.8f}, {1.4f, 1.1f, 1.9f}, {2.2f, 0.9f, 1.6f}, kRadiance, false},
         SphereEmitter{{-0.6f, 1.4f, 1.5f}, 0.4f, kRadiance});
    // A point on a wall: half of what it sees lies below z = 0, where directions about +z that
    // were never turned to the normal do not go.
    make("D3 a point on a wall (normal +x), lights in front of it reaching below z = 0", at(Vec3(0.0f), {1.0f, 0.0f, 0.0f}),
         TriangleEmitter{{1.2f, -0.5f, -1.0f}, {1.2f, 0.0f, 0.4f}, {1.2f, 0.6f, -0.8f}, kRadiance, false},  // facing -x
         SphereEmitter{{1.6f, 1.2f, -0.7f}, 0.35f, kRadiance});
    return cases;
}

}  // namespace rtlab::grader
