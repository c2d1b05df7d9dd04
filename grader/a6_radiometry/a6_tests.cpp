// Assignment a6: radiometry and Monte Carlo direct lighting (docs/a6-radiometry.md#how-the-grader-checks-it).
// Units and solid angles by truth tables derived by hand from the definitions; samplers by their
// pinned mapping (a truth table on given u, and samples the grader picks against the u they were
// drawn from), by Pearson's chi-square test over exact expected counts, two-sided (10^6 samples
// a run, alpha = 0.01 with Sidak's correction over a test's runs: a fit too good to be random
// fails as a bad one does) and by the pdf they report; estimators on cases drawn from the
// grading seed, by z tests of their means against closed forms and of their samples' variance
// against the estimator's own (alpha = 0.01, Sidak over a test's cases), a failing mean named
// by the common mistake it matches; plain Monte Carlo's convergence by the slope of its RMS
// error. The worker returns raw values and samples; every statistic is here, and a malformed
// record fails only the test it belongs to.
#include "framework/core/pcg32.h"
#include "framework/oracle/closed_forms.h"
#include "grader/a6_radiometry/a6_tests.h"
#include "grader/kit/truth_table.h"
#include "grader/a6_radiometry/radiometry_cases.h"
#include "grader/a6_radiometry/sampler_histograms.h"
#include "grader/a6_radiometry/sampler_mappings.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"
#include "grader/kit/accelerator_checks.h"
#include "grader/kit/statistics.h"
#include "grader/wire/scene_codec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace rtlab::grader {
namespace {

using worker::Estimator;
using worker::Sampler;

constexpr const char* kA6 = "a6";
const std::string kStubUnits = a6Stubs().file("units.cpp", "units");
const std::string kStubSolidAngles = a6Stubs().file("solid_angle.cpp", "solid angles");
const std::string kStubSamplers = a6Stubs().file("samplers.cpp", "samplers");
const std::string kStubSphericalTriangle = a6Stubs().name("sampleSphericalTriangle");
const std::string kStubLightEstimators = a6Stubs().file("light_estimators.cpp", "light estimators");
const std::string kStubDirectionEstimators = a6Stubs().file("direction_estimators.cpp", "estimators by direction");

constexpr double kPi = std::numbers::pi;
constexpr double kAlpha = 0.01;
constexpr uint32_t kSamplesPerRun = 1000000;
// Truth tables in double: the pinned formulas leave only rounding (the expected values are
// computed another way).
constexpr double kTableTolerance = 1e-9;

bool close(double got, double expected, double relative) {
    if (std::isinf(expected)) return got == expected;
    return std::abs(got - expected) <= relative * std::max(std::abs(expected), 1e-300) || got == expected;
}

std::string vec(const DVec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
    return text;
}

std::string pair(Vec2 u) {
    char text[64];
    std::snprintf(text, sizeof text, "(%.9g, %.9g)", u.x, u.y);
    return text;
}

// Scores one test from the worker's raw results: a record that is malformed or ends early fails
// this test alone, under its own name, whatever the other tests' records hold.
void scoreGuarded(TestResult& result, const std::function<void()>& score) {
    try {
        score();
    } catch (const WireError& e) {
        result.details.clear();
        markFailed(result, std::string("sent malformed results: ") + e.what());
    }
}

// --- Truth tables: units, solid angles, the sphere integral, pdf conversion -------------------

struct ValueCase {
    std::string id;  // what the case is and how its answer follows from the definition
    double expected;
};

// One phase per table: the worker writes one f64 (or f32) per call, in order.
template <typename Call, typename Value = double>
TestGroup valueTable(const char* title, const char* test, const std::string& stub, const char* task,
                     std::vector<std::pair<Call, ValueCase>> table, double tolerance = kTableTolerance) {
    using Case = TableCase<Call, double>;
    std::vector<Case> cases;
    for (auto& [call, c] : table) cases.push_back({c.id, call, c.expected});
    return tableGroup(kA6, title, test, stub, task, std::move(cases), [tolerance](const Case& c, ByteReader& in) {
        double got = in.get<Value>();
        return close(got, c.expected, tolerance) ? std::string() : expectedGot(formatNumber(c.expected), formatNumber(got));
    });
}

TestGroup unitsGroup() {
    using F = worker::UnitFunction;
    using C = worker::UnitCall;
    return valueTable<C>("a6 units", "a6/units/conversions", kStubUnits, worker::kTaskUnits,
                         {
                             {C{F::EnergyFromPower, 60, 3600, 0}, {"a 60 W lamp for an hour: Q = 60 W * 3600 s", 216000.0}},
                             {C{F::PowerFromEnergy, 1000, 8, 0}, {"1000 J in 8 s: Phi = Q / t", 125.0}},
                             {C{F::IntensityFromPower, 100, 0, 0}, {"100 W, isotropic: I = 100 / (4 pi) = 25 / pi", 25.0 / kPi}},
                             {C{F::PowerFromIntensity, 1, 0, 0}, {"1 W/sr in every direction: Phi = 4 pi", 4.0 * kPi}},
                             {C{F::IrradianceFromIntensity, 10, 2, 0.5}, {"10 W/sr at 2 m, 60 degrees off: E = 10 * 0.5 / 2^2", 1.25}},
                             {C{F::RadianceFromPower, kPi, 2, 0}, {"pi W from 2 m^2, one-sided Lambertian: L = pi / (pi * 2)", 0.5}},
                             {C{F::PowerFromRadiance, 3, 0.5, 0}, {"L = 3 from 0.5 m^2: Phi = pi * 3 * 0.5", 1.5 * kPi}},
                             {C{F::IrradianceFromRadiance, 1, 0, 0}, {"L = 1 from the whole hemisphere: E = pi", kPi}},
                             {C{F::LumensFromWatts, 2, 0, 0}, {"2 W at 555 nm: 2 * 683 lm", 1366.0}},
                             {C{F::WattsFromLumens, 683, 0, 0}, {"683 lm at 555 nm: 1 W", 1.0}},
                             {C{F::WattsFromLumens, 1000, 0, 0}, {"1000 cd = 1000 lm/sr: 1000 / 683 W/sr", 1000.0 / 683.0}},
                         });
}

worker::SolidAngleCall solidAngleCall(worker::SolidAngleFunction f, double x, double y, DVec3 p = {}, DVec3 a = {}, DVec3 b = {},
                                      DVec3 c = {}) {
    return {f, x, y, p, a, b, c};
}

std::vector<TestGroup> solidAngleGroups() {
    using F = worker::SolidAngleFunction;
    using C = worker::SolidAngleCall;
    // Cones and spheres: 2 pi (1 - cos a) written as 4 pi sin^2(a / 2) with a = asin(r / d).
    auto cap = [](double halfAngle) { return 4.0 * kPi * std::pow(std::sin(halfAngle / 2.0), 2); };
    const double sunRadius = 6.957e8, sunDistance = 1.496e11;  // m: IAU nominal solar radius, 1 au
    std::vector<std::pair<C, ValueCase>> cones{
        {solidAngleCall(F::Cone, kPi / 2, 0), {"a cone of half-angle pi/2 is a hemisphere: 2 pi", 2.0 * kPi}},
        {solidAngleCall(F::Cone, kPi, 0), {"half-angle pi: the whole sphere, 4 pi", 4.0 * kPi}},
        {solidAngleCall(F::Cone, kPi / 3, 0), {"half-angle pi/3: 2 pi (1 - 1/2) = pi", kPi}},
        {solidAngleCall(F::Cone, 1e-8, 0), {"half-angle 1e-8 (a star): pi a^2 = pi 1e-16, where 1 - cos a is 0 in double", cap(1e-8)}},
        {solidAngleCall(F::Sphere, sunRadius, sunDistance),
         {"the Sun from the Earth, r = 6.957e8 m at 1.496e11 m: about 6.8e-5 sr", cap(std::asin(sunRadius / sunDistance))}},
        {solidAngleCall(F::Sphere, 1.0, std::sqrt(2.0)), {"a sphere at r sqrt(2): a cap of 45 degrees, 2 pi (1 - 1/sqrt(2))",
                                                          2.0 * kPi * (1.0 - std::sqrt(0.5))}},
        {solidAngleCall(F::Sphere, 1.0, 1e9), {"r / d = 1e-9: pi 1e-18", cap(std::asin(1e-9))}},
        {solidAngleCall(F::Sphere, 2.0, 1.0), {"a point inside the sphere: 4 pi", 4.0 * kPi}},
        {solidAngleCall(F::Sphere, 1.0, 1.0), {"a point on the sphere (distance = radius): 4 pi", 4.0 * kPi}},
    };
    // Triangles: the octant and a tetrahedron's face by symmetry; others by Girard's angle excess
    // (framework/oracle/closed_forms.h), a formula of its own.
    DVec3 o(0.0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), shift(1, 2, 3);
    DVec3 big0(-10, -10, 0.1), big1(10, -10, 0.1), big2(0, 20, 0.1);
    DVec3 far0(100, 3, 2), far1(100, 4, 2.5), far2(101, 3.5, 3);
    std::vector<std::pair<C, ValueCase>> triangles{
        {solidAngleCall(F::Triangle, 0, 0, o, x, y, z), {"the octant's triangle (1,0,0), (0,1,0), (0,0,1) from the origin: 4 pi / 8", kPi / 2}},
        {solidAngleCall(F::Triangle, 0, 0, shift, shift + 5.0 * x, shift + 5.0 * z, shift + 5.0 * y),
         {"the same moved to (1,2,3), scaled by 5, in the other order (unsigned)", kPi / 2}},
        {solidAngleCall(F::Triangle, 0, 0, o, {1, 1, 1}, {1, -1, -1}, {-1, 1, -1}), {"a regular tetrahedron's face from its centre: 4 pi / 4", kPi}},
        {solidAngleCall(F::Triangle, 0, 0, o, big0, big1, big2),
         {"a large triangle 0.1 above the point: more than pi (atan2, not atan)", triangleSolidAngleByExcess(o, big0, big1, big2)}},
        {solidAngleCall(F::Triangle, 0, 0, o, far0, far1, far2), {"a small triangle 100 m away", triangleSolidAngleByExcess(o, far0, far1, far2)}},
        {solidAngleCall(F::Triangle, 0, 0, {5, 5, 0}, o, x, y), {"the point in the triangle's plane, outside it: 0", 0.0}},
    };
    // Rectangles 2a x 2b seen on their axis from h: 4 asin(a b / sqrt((a^2 + h^2)(b^2 + h^2))).
    DVec3 p(0.3, -0.2, 0.0), corner(-0.5, -0.5, 1.0), u(1, 0, 0), v(0, 1, 0);
    std::vector<std::pair<C, ValueCase>> rectangles{
        {solidAngleCall(F::Rectangle, 0, 0, o, {-1, -1, 1}, {2, 0, 0}, {0, 2, 0}), {"a cube's face from its centre: 4 pi / 6", 4.0 * kPi / 6.0}},
        {solidAngleCall(F::Rectangle, 0, 0, {0, 0, 2}, {-1, -1, 1}, {0, 2, 0}, {2, 0, 0}),
         {"the same face from outside, edges in the other order: 4 asin(1/2)", 4.0 * std::asin(0.5)}},
        {solidAngleCall(F::Rectangle, 0, 0, o, corner, u, v), {"a unit square 1 away on its axis: 4 asin(0.25 / 1.25)", 4.0 * std::asin(0.2)}},
        {solidAngleCall(F::Rectangle, 0, 0, p, corner, u, v),
         {"the unit square seen off its axis",
          triangleSolidAngleByExcess(p, corner, corner + u, corner + u + v) + triangleSolidAngleByExcess(p, corner, corner + u + v, corner + v)}},
    };
    // The midpoint rule has closed forms: with h = pi / n, sum_i sin((i + 1/2) h) = 1 / sin(h/2),
    // so f = 1 gives 2 pi h / sin(h/2); for even n, sum over the upper half of
    // sin cos = 1 / (2 sin h), so f = max(0, cos theta) gives pi h / sin h. The phi sum of
    // cos((j + 1/2) 2 pi / m) is 0 for m >= 2 and cos(pi) = -1 for m = 1.
    using I = worker::Integrand;
    using G = worker::IntegralCall;
    auto one = [](int n) { double h = kPi / n; return 2.0 * kPi * h / std::sin(h / 2.0); };
    auto lambert = [](int n) { double h = kPi / n; return kPi * h / std::sin(h); };
    std::vector<std::pair<G, ValueCase>> integrals{
        {G{I::One, 1, 1}, {"f = 1 on one cell: theta = pi/2, phi = pi, 2 pi^2", 2.0 * kPi * kPi}},
        {G{I::One, 100, 3}, {"f = 1, 100 x 3 cells: 2 pi h / sin(h/2), h = pi/100", one(100)}},
        {G{I::One, 2000, 1}, {"f = 1, 2000 x 1 cells: 4 pi within 1e-6", one(2000)}},
        {G{I::PositiveCosine, 64, 8}, {"f = max(0, cos theta) (a Lambertian source, I0 = 1: Phi = pi), 64 x 8: pi h / sin h", lambert(64)}},
        {G{I::OnePlusCosPhi, 10, 1}, {"f = 1 + cos phi on one phi cell: its centre is phi = pi, so 0", 0.0}},
        {G{I::OnePlusCosPhi, 10, 4}, {"f = 1 + cos phi on 4 phi cells: the cosines cancel, as f = 1", one(10)}},
    };
    return {valueTable<C>("a6 solid angles of cones and spheres", "a6/solid-angle/cone-and-sphere", kStubSolidAngles, worker::kTaskSolidAngles, cones),
            valueTable<C>("a6 solid angles of triangles", "a6/solid-angle/triangle", kStubSolidAngles, worker::kTaskSolidAngles, triangles),
            valueTable<C>("a6 solid angles of rectangles", "a6/solid-angle/rectangle", kStubSolidAngles, worker::kTaskSolidAngles, rectangles),
            valueTable<G>("a6 the integral of dOmega", "a6/solid-angle/sphere-integral", kStubSolidAngles, worker::kTaskSphereIntegrals, integrals)};
}

TestGroup pdfConversionGroup() {
    using C = worker::PdfCall;
    const double inf = std::numeric_limits<double>::infinity();
    return valueTable<C, float>("a6 area to solid-angle pdf", "a6/samplers/area-to-solid-angle", kStubSamplers, worker::kTaskPdfConversions,
                                {
                                    {C{0.5f, 4.0f, 0.5f}, {"pdfArea 0.5, d^2 = 4, cos 0.5: 0.5 * 4 / 0.5", 4.0}},
                                    {C{0.25f, 9.0f, -0.75f}, {"cos -0.75 (the light's back): |cos|, 0.25 * 9 / 0.75", 3.0}},
                                    {C{2.0f, 1.0f, 1.0f}, {"facing the point at distance 1: unchanged", 2.0}},
                                    {C{1.0f, 1.0f, 0.0f}, {"a grazing light point: infinite", inf}},
                                },
                                1e-6);
}

// --- Samplers: the pinned mapping, the histogram and the pdf --------------------------------

// One row of a mapping's truth table: u, and the sample the contract pins for it, derived by
// hand.
struct MappingRow {
    std::string id;  // "u = (0.25, 0): z = 0.5, phi = 0"
    Vec2 u;
    DVec3 expected;
};

// What one sampler is judged against: its mapping on given u and on samples of its runs the
// grader picks, and the runs' histograms and densities.
struct SamplerTarget {
    std::string test;
    std::string stub;
    worker::SamplerCall tableCall;  // the configuration (cone, triangle) the truth table maps u in
    std::vector<MappingRow> table;
    std::vector<worker::SamplerCall> runs;
    uint64_t seed = 0;       // the grading seed: which samples of the runs are checked
    bool directions = true;  // unit vectors (else points of a triangle)
    // Per run: the histogram cell of a sample and the expected count of every cell.
    std::function<size_t(size_t run, const Vec3& value)> cellOf;
    std::function<std::vector<double>(size_t run)> expected;
    std::function<std::string(size_t run, size_t cell)> describe;
    // The density of a sample, and how the contract writes it.
    std::function<double(size_t run, const Vec3& value)> pdf;
    std::string pdfFormula;
};

// Samples of each run checked against the pinned mapping of their u.
constexpr size_t kMappedSamplesPerRun = 4096;

// Every run draws its own numbers, from the grading seed, the sampler and the run.
worker::SamplerCall samplerCall(Sampler sampler, size_t run, uint64_t seed) {
    worker::SamplerCall c{};
    c.sampler = sampler;
    c.seed = worker::callSeed(seed, 1000 + static_cast<uint64_t>(sampler), run);
    c.count = kSamplesPerRun;
    return c;
}

// Directions with a distribution uniform in phi and F for z on [zMin, 1].
SamplerTarget directionTarget(std::string test, Sampler sampler, uint64_t seed, std::vector<float> conesOrNone,
                              std::function<double(float, double)> zCdf, std::function<double(float, const Vec3&)> pdf, std::string formula) {
    SamplerTarget t;
    t.test = std::move(test);
    t.stub = kStubSamplers;
    t.seed = seed;
    for (size_t run = 0; run < conesOrNone.size(); ++run) {
        worker::SamplerCall c = samplerCall(sampler, run, seed);
        c.cosThetaMax = conesOrNone[run];
        t.runs.push_back(c);
    }
    auto zMin = [conesOrNone, sampler](size_t run) {
        if (sampler == Sampler::UniformSphere) return -1.0;
        if (sampler == Sampler::UniformCone) return double(conesOrNone[run]);
        return 0.0;
    };
    t.cellOf = [zMin](size_t run, const Vec3& v) { return DirectionBins{zMin(run)}.cellOf(v); };
    t.expected = [zMin, zCdf, conesOrNone](size_t run) {
        float cosMax = conesOrNone[run];
        return DirectionBins{zMin(run)}.expected(kSamplesPerRun, [&](double z) { return zCdf(cosMax, z); });
    };
    t.describe = [zMin](size_t run, size_t cell) { return DirectionBins{zMin(run)}.describe(cell); };
    t.pdf = [pdf, conesOrNone](size_t run, const Vec3& v) { return pdf(conesOrNone[run], v); };
    t.pdfFormula = std::move(formula);
    return t;
}

// The truth tables of the direction samplers: (r cos phi, r sin phi, z) with phi = 2 pi u.y and
// r = sqrt(1 - z^2), z as each contract says.
std::vector<SamplerTarget> directionTargets(uint64_t seed) {
    const std::vector<float> three(3, 0.0f);
    const double h = std::sqrt(0.5), s = std::sqrt(0.75);  // cos 45 degrees; r at z = 1/2
    SamplerTarget sphere = directionTarget("a6/samplers/uniform-sphere", Sampler::UniformSphere, seed, three,
                                           [](float, double z) { return (z + 1.0) / 2.0; }, [](float, const Vec3&) { return 1.0 / (4.0 * kPi); }, "1/(4 pi)");
    sphere.table = {{"u = (0, 0): z = 1, the pole", {0.0f, 0.0f}, {0, 0, 1}},
                    {"u = (0.25, 0): z = 1/2, phi = 0", {0.25f, 0.0f}, {s, 0, 0.5}},
                    {"u = (0.5, 0.25): z = 0, phi = pi/2", {0.5f, 0.25f}, {0, 1, 0}},
                    {"u = (0.75, 0.625): z = -1/2, phi = 5 pi/4", {0.75f, 0.625f}, {-s * h, -s * h, -0.5}},
                    {"u = (0.875, 0.5): z = -3/4, phi = pi", {0.875f, 0.5f}, {-std::sqrt(1.0 - 0.5625), 0, -0.75}}};
    SamplerTarget hemisphere = directionTarget("a6/samplers/uniform-hemisphere", Sampler::UniformHemisphere, seed, three,
                                               [](float, double z) { return z; }, [](float, const Vec3&) { return 1.0 / (2.0 * kPi); }, "1/(2 pi)");
    hemisphere.table = {{"u = (0.5, 0.125): z = 1/2, phi = pi/4", {0.5f, 0.125f}, {s * h, s * h, 0.5}},
                        {"u = (0, 0.5): z = 0, phi = pi", {0.0f, 0.5f}, {-1, 0, 0}},
                        {"u = (0.8, 0.75): z = 0.8, phi = 3 pi/2", {0.8f, 0.75f}, {0, -0.6, 0.8}},
                        {"u = (0.6, 0): z = 0.6, phi = 0", {0.6f, 0.0f}, {0.8, 0, 0.6}}};
    SamplerTarget cosine = directionTarget("a6/samplers/cosine-hemisphere", Sampler::CosineHemisphere, seed, three,
                                           [](float, double z) { return z * z; }, [](float, const Vec3& v) { return v.z / kPi; }, "cos(theta)/pi");
    cosine.table = {{"u = (0.36, 0): r = 0.6 on the disk, z = 0.8", {0.36f, 0.0f}, {0.6, 0, 0.8}},
                    {"u = (0.64, 0.25): r = 0.8, z = 0.6, phi = pi/2", {0.64f, 0.25f}, {0, 0.8, 0.6}},
                    {"u = (0, 0.3): r = 0, the normal", {0.0f, 0.3f}, {0, 0, 1}},
                    {"u = (0.5, 0.5): r = z = sqrt(1/2), phi = pi", {0.5f, 0.5f}, {-h, 0, h}},
                    {"u = (0.96, 0.75): r = sqrt(0.96), z = 0.2, phi = 3 pi/2", {0.96f, 0.75f}, {0, -std::sqrt(0.96), 0.2}}};
    SamplerTarget cone = directionTarget("a6/samplers/uniform-cone", Sampler::UniformCone, seed, {0.9f, 0.2f, -0.5f},
                                         [](float c, double z) { return (z - c) / (1.0 - c); },
                                         [](float c, const Vec3&) { return 1.0 / (2.0 * kPi * (1.0 - double(c))); }, "1/(2 pi (1 - cosThetaMax))");
    cone.tableCall.cosThetaMax = 0.6f;
    cone.table = {{"cosThetaMax 0.6, u = (0.5, 0): z = 1 - 0.5 * 0.4 = 0.8", {0.5f, 0.0f}, {0.6, 0, 0.8}},
                  {"cosThetaMax 0.6, u = (0.25, 0.25): z = 0.9, phi = pi/2", {0.25f, 0.25f}, {0, std::sqrt(0.19), 0.9}},
                  {"cosThetaMax 0.6, u = (0, 0.7): the axis", {0.0f, 0.7f}, {0, 0, 1}},
                  {"cosThetaMax 0.6, u = (0.875, 0.5): z = 0.65, phi = pi", {0.875f, 0.5f}, {-std::sqrt(1.0 - 0.4225), 0, 0.65}}};
    std::vector<SamplerTarget> targets{std::move(sphere), std::move(hemisphere), std::move(cosine), std::move(cone)};
    for (SamplerTarget& t : targets) t.tableCall.sampler = t.runs.front().sampler;
    return targets;
}

SamplerTarget triangleTarget(uint64_t seed) {
    struct Run {
        DVec3 p0, p1, p2;
    };
    std::vector<Run> triangles{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                               {{-1, 2, 0.5}, {3, 2.5, -1}, {0.5, -1, 2}},
                               {{100, 100, 100}, {100.5, 100, 100}, {100, 100.01, 100.3}}};
    SamplerTarget t;
    t.test = "a6/samplers/uniform-triangle";
    t.stub = kStubSamplers;
    t.seed = seed;
    t.directions = false;
    // p0 + b1 (2, 0, 0) + b2 (0, 0, 2) with s = sqrt(u.x), b1 = u.y s, b2 = s - b1.
    t.tableCall.sampler = Sampler::UniformTriangle;
    t.tableCall.p0 = {1, 2, 3}, t.tableCall.p1 = {3, 2, 3}, t.tableCall.p2 = {1, 2, 5};
    t.table = {{"p0 (1, 2, 3), p1 (3, 2, 3), p2 (1, 2, 5), u = (0, 0.5): s = 0, p0", {0.0f, 0.5f}, {1, 2, 3}},
               {"u = (0.25, 0.5): s = 1/2, b = (1/2, 1/4, 1/4)", {0.25f, 0.5f}, {1.5, 2, 3.5}},
               {"u = (0.81, 0): s = 0.9, b = (0.1, 0, 0.9)", {0.81f, 0.0f}, {1, 2, 4.8}},
               {"u = (0.64, 0.75): s = 0.8, b = (0.2, 0.6, 0.2)", {0.64f, 0.75f}, {2.2, 2, 3.4}},
               {"u close to (1, 1): s and b1 close to 1, p1", {0x1.fffffep-1f, 0x1.fffffep-1f}, {3, 2, 3}}};
    for (size_t run = 0; run < triangles.size(); ++run) {
        worker::SamplerCall c = samplerCall(Sampler::UniformTriangle, run, seed);
        c.p0 = Vec3(triangles[run].p0), c.p1 = Vec3(triangles[run].p1), c.p2 = Vec3(triangles[run].p2);
        t.runs.push_back(c);
    }
    // The bins of the float triangle the sampler gets.
    auto bins = [runs = t.runs](size_t run) { return TriangleBins{DVec3(runs[run].p0), DVec3(runs[run].p1), DVec3(runs[run].p2)}; };
    t.cellOf = [bins](size_t run, const Vec3& v) { return bins(run).cellOf(DVec3(v)); };
    t.expected = [bins](size_t run) {
        TriangleBins b = bins(run);
        std::vector<double> counts(b.cells(), double(kSamplesPerRun) / (b.k * b.k));
        counts.back() = 0.0;
        return counts;
    };
    t.describe = [bins](size_t run, size_t cell) { return bins(run).describe(cell); };
    t.pdf = [bins](size_t run, const Vec3&) {
        TriangleBins b = bins(run);
        return 2.0 / glm::length(glm::cross(b.p1 - b.p0, b.p2 - b.p0));
    };
    t.pdfFormula = "1/area";
    return t;
}

SamplerTarget sphericalTriangleTarget(uint64_t seed) {
    struct Run {
        DVec3 p, p0, p1, p2;
    };
    std::vector<Run> configurations{{{0, 0, 0}, {-0.5, -0.4, 1}, {0.1, 0.7, 0.9}, {0.6, -0.3, 1.2}},
                                    {{0.2, 0.1, 0.05}, {-3, -3, 0.3}, {3, -3, 0.3}, {0, 4, 0.3}},
                                    {{0, 0, 0}, {4, 0.1, 0.2}, {4, 0.3, 0.1}, {4.2, 0.2, 0.3}}};
    SamplerTarget t;
    t.test = "a6/samplers/spherical-triangle";
    t.stub = kStubSphericalTriangle;
    t.seed = seed;
    // The octant's triangle seen from p: A = +x, B = +y, C = +z. B is the pole of the great
    // circle through A and C, so the sub-triangle A, B, C' with C' at the angle t from A has
    // the angles pi/2, t, pi/2 and the area t (Girard): u.x pi/2 of the octant's pi/2 puts C' at
    // t = u.x pi/2. C' . B = 0, so the direction is z B + sqrt(1 - z^2) C' with z = 1 - u.y.
    t.tableCall.sampler = Sampler::SphericalTriangle;
    t.tableCall.p = {1, 2, 3}, t.tableCall.p0 = {3, 2, 3}, t.tableCall.p1 = {1, 4, 3}, t.tableCall.p2 = {1, 2, 5};
    auto octant = [](double ux, double uy) {
        double z = 1.0 - uy, r = std::sqrt(1.0 - z * z), angle = ux * kPi / 2.0;
        return DVec3(r * std::cos(angle), z, r * std::sin(angle));
    };
    t.table = {{"the octant (1, 2, 3) + 2 (x, y, z) seen from (1, 2, 3), u = (0.5, 0.5): t = pi/4, z = 1/2", {0.5f, 0.5f}, octant(0.5, 0.5)},
               {"u = (0, 0.2): C' = A, z = 0.8", {0.0f, 0.2f}, {0.6, 0.8, 0}},
               {"u = (0.75, 0): z = 1, B", {0.75f, 0.0f}, {0, 1, 0}},
               {"u = (1/3, 0.9): t = pi/6, z = 0.1", {1.0f / 3.0f, 0.9f}, octant(1.0f / 3.0f, 0.9f)},
               {"u = (0.875, 0.5): t = 7 pi/16, z = 1/2", {0.875f, 0.5f}, octant(0.875, 0.5)}};
    for (size_t run = 0; run < configurations.size(); ++run) {
        worker::SamplerCall c = samplerCall(Sampler::SphericalTriangle, run, seed);
        const Run& r = configurations[run];
        c.p = Vec3(r.p), c.p0 = Vec3(r.p0), c.p1 = Vec3(r.p1), c.p2 = Vec3(r.p2);
        t.runs.push_back(c);
    }
    auto bins = [runs = t.runs](size_t run) { return TriangleBins{DVec3(runs[run].p0), DVec3(runs[run].p1), DVec3(runs[run].p2)}; };
    auto from = [runs = t.runs](size_t run) { return DVec3(runs[run].p); };
    auto omega = [bins, from](size_t run) {
        TriangleBins b = bins(run);
        return triangleSolidAngleByExcess(from(run), b.p0, b.p1, b.p2);
    };
    t.cellOf = [bins, from](size_t run, const Vec3& v) { return bins(run).cellOfDirection(from(run), DVec3(v)); };
    // Each sub-triangle expects its share of the solid angle.
    t.expected = [bins, from, omega](size_t run) {
        TriangleBins b = bins(run);
        std::vector<double> counts;
        for (const auto& s : b.subTriangles()) counts.push_back(kSamplesPerRun * triangleSolidAngleByExcess(from(run), s[0], s[1], s[2]) / omega(run));
        counts.push_back(0.0);
        return counts;
    };
    t.describe = [bins](size_t run, size_t cell) { return bins(run).describe(cell); };
    t.pdf = [omega](size_t run, const Vec3&) { return 1.0 / omega(run); };
    t.pdfFormula = "1/Omega";
    return t;
}

// The samples of run `run` the grader checks against the mapping, in increasing order: drawn
// from the grading seed, so a sampler cannot know which.
std::vector<uint32_t> checkedSamples(const SamplerTarget& t, size_t run) {
    Pcg32 pick(worker::callSeed(t.seed, 2000 + static_cast<uint64_t>(t.runs[run].sampler), run), 0);
    std::vector<uint32_t> indices;
    for (size_t i = 0; i < kMappedSamplesPerRun; ++i) indices.push_back(pick.next() % t.runs[run].count);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    return indices;
}

// The mapping: every row of the truth table, then the picked samples of every run against the
// pinned mapping of the u the worker drew them from (the same PCG32 replayed here). The problem,
// or "".
std::string judgeMapping(const SamplerTarget& t, const std::vector<worker::SampleResult>& table,
                         const std::vector<std::vector<worker::SampleResult>>& runs, std::vector<std::string>& details) {
    const char* why = " (each sampler's mapping is pinned by its contract, framework/interface/a6_radiometry.h)";
    if (table.size() != t.table.size()) return std::to_string(table.size()) + " samples for " + std::to_string(t.table.size()) + " given u";
    size_t wrongRows = 0;
    std::string first;
    for (size_t i = 0; i < t.table.size(); ++i) {
        const MappingRow& row = t.table[i];
        DVec3 got(table[i].value);
        if (glm::length(got - row.expected) <= pinnedTolerance(t.tableCall)) continue;
        std::string line = row.id + ": expected " + vec(row.expected) + ", got " + vec(got);
        details.push_back("mapping " + line);
        if (wrongRows++ == 0) first = line;
    }
    size_t checked = 0, wrong = 0;
    std::string firstSample;
    for (size_t k = 0; k < t.runs.size(); ++k) {
        const worker::SamplerCall& call = t.runs[k];
        if (runs[k].size() != call.count) continue;  // the run's own case says so
        std::vector<uint32_t> picked = checkedSamples(t, k);
        Pcg32 rng(call.seed, 0);
        size_t next = 0;
        for (uint32_t i = 0; i < call.count && next < picked.size(); ++i) {
            Vec2 u = worker::uniformPair(rng);
            if (i != picked[next]) continue;
            ++next;
            ++checked;
            DVec3 pinned = pinnedSample(call, u), got(runs[k][i].value);
            double off = glm::length(got - pinned);
            if (off <= pinnedTolerance(call)) continue;
            if (wrong++ == 0)
                firstSample = "run " + std::to_string(k + 1) + ", sample " + std::to_string(i) + " drawn with u = " + pair(u) + ": " + vec(got) +
                              " where the mapping gives " + vec(pinned) + " (off by " + formatNumber(off) + ", tolerance " +
                              formatNumber(pinnedTolerance(call)) + ")";
        }
    }
    details.push_back(std::to_string(checked - wrong) + " of " + std::to_string(checked) +
                      " samples picked from the runs are the pinned mapping of the u they were drawn from" +
                      (wrong > 0 ? "; first that is not: " + firstSample : ""));
    if (wrongRows > 0) return std::to_string(wrongRows) + " of " + std::to_string(t.table.size()) + " given u map elsewhere" + why + "; first: " + first;
    if (wrong > 0)
        return std::to_string(wrong) + " of " + std::to_string(checked) + " samples are not the pinned mapping of the u they were drawn from" + why +
               "; first: " + firstSample;
    return "";
}

// The problems of one run, or "" when it passes at level `alpha`: both tails of the
// chi-square distribution, alpha/2 each.
std::string judgeRun(const SamplerTarget& t, size_t run, const std::vector<worker::SampleResult>& samples, double alpha,
                     std::vector<std::string>& details) {
    std::string tag = "run " + std::to_string(run + 1);
    if (samples.size() != t.runs[run].count) return std::to_string(samples.size()) + " samples for " + std::to_string(t.runs[run].count);
    std::vector<double> observed(t.expected(run).size(), 0.0);
    for (size_t i = 0; i < samples.size(); ++i) {
        const Vec3& v = samples[i].value;
        // Written only for the sample that fails: formatting every one cost more than judging it.
        auto where = [&] { return "sample " + std::to_string(i) + " " + vec(DVec3(v)); };
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(samples[i].pdf))
            return where() + ": not finite (pdf " + formatNumber(samples[i].pdf) + ")";
        if (t.directions && std::abs(glm::length(DVec3(v)) - 1.0) > 1e-4) return where() + ": not of unit length";
        double density = t.pdf(run, v);
        if (std::abs(samples[i].pdf - density) > 1e-3 * density + 1e-6)
            return where() + ": pdf " + formatNumber(samples[i].pdf) + ", but the density of this sample is " + t.pdfFormula + " = " +
                   formatNumber(density) + " (the pdf must be the one of the sample returned)";
        observed[t.cellOf(run, v)] += 1.0;
    }
    std::vector<double> expected = t.expected(run);
    ChiSquareResult chi = chiSquareTest(observed, expected);
    size_t worst = chi.worstCell;
    std::string fit = "chi^2 = " + formatNumber(chi.chiSquare) + " with " + std::to_string(chi.dof) + " degrees of freedom";
    std::string mostOff = "most off: " + t.describe(run, worst) + ", " + formatNumber(observed[worst]) + " samples for " +
                          formatNumber(expected[worst]) + " expected";
    details.push_back(tag + ": " + fit + ", P(chi^2 >= that) = " + formatNumber(chi.p) + ", P(chi^2 <= that) = " + formatNumber(chi.pLower) +
                      " (" + std::to_string(chi.pooledCells) + " cells pooled); " + mostOff);
    if (chi.outsideObserved > 0)
        return formatNumber(chi.outsideObserved) + " of " + std::to_string(samples.size()) + " samples " + t.describe(run, observed.size() - 1) +
               ", where the density is 0";
    if (!(chi.p >= alpha / 2))
        return "the samples do not follow the distribution (" + fit + ", p = " + formatNumber(chi.p) + " < " + formatNumber(alpha / 2) + "); " +
               mostOff;
    if (!(chi.pLower >= alpha / 2))
        return "the samples fit the histogram better than independent samples can (" + fit + ", P(chi^2 <= that) = " + formatNumber(chi.pLower) +
               " < " + formatNumber(alpha / 2) + "): too good to be random, as samples placed by quota are";
    return "";
}

TestGroup samplerGroup(std::shared_ptr<const SamplerTarget> t) {
    TestGroup group;
    group.assignment = kA6;
    group.title = t->test;
    ByteWriter givenInput;
    givenInput.put(t->tableCall);
    std::vector<Vec2> given;
    for (const MappingRow& row : t->table) given.push_back(row.u);
    givenInput.putVector(given);
    group.phases.push_back(makePhase(t->stub, worker::kTaskSamplesAt, std::move(givenInput)));
    for (const worker::SamplerCall& call : t->runs) {
        ByteWriter input;
        input.put(call);
        group.phases.push_back(makePhase(t->stub, worker::kTaskSamples, std::move(input)));
    }
    group.score = [t](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, t->test);
        for (const PhaseOutcome& phase : run.phases)
            if (failedPhaseResult(phase, result)) {
                results.push_back(std::move(result));
                return;
            }
        scoreGuarded(result, [&] {
            std::vector<worker::SampleResult> table = ByteReader(run.phases[0].data).getVector<worker::SampleResult>(t->table.size());
            std::vector<std::vector<worker::SampleResult>> samples;
            for (size_t k = 0; k < t->runs.size(); ++k)
                samples.push_back(ByteReader(run.phases[k + 1].data).getVector<worker::SampleResult>(worker::kMaxSamplesPerCall));
            // Sidak over the runs: the family keeps alpha = 0.01.
            double alpha = sidakLevel(kAlpha, static_cast<int>(t->runs.size()));
            CaseTally tally(result);
            std::vector<std::string> details;
            tally.record("the pinned mapping", judgeMapping(*t, table, samples, details));
            for (size_t k = 0; k < t->runs.size(); ++k) tally.record("run " + std::to_string(k + 1), judgeRun(*t, k, samples[k], alpha, details));
            tally.finish();
            result.details.insert(result.details.end(), details.begin(), details.end());
        });
        results.push_back(std::move(result));
    };
    return group;
}

// --- Estimators: z tests of the mean and of the spread, and the mistakes they match ----------

// How closely the grader's quadrature gives an estimator's variance (radiometry_cases.cpp: the
// midpoint rule on 64^2 sub-triangles of a triangle, 256^2 cells of a sphere's cap); a sample
// variance may differ from it by this much besides the noise.
constexpr double kSpreadAccuracy = 0.005;

ChildPhase estimatorPhase(const std::string& stub, const std::vector<EstimatorCase>& cases) {
    ByteWriter input;
    input.put<uint64_t>(cases.size());
    for (const EstimatorCase& c : cases) {
        writeScene(c.scene, input);
        input.put(c.call);
    }
    return makePhase(stub, worker::kTaskEstimates, std::move(input));
}

const char* kChannels[] = {"red", "green", "blue"};

// The mistake a mean matches, if any: within 4 standard errors (and 1 % for the quadrature),
// and itself clearly away from the right answer.
std::string matchingMistake(const EstimatorCase& c, int channel, const MeanEstimate& m) {
    double se = m.standardError();
    for (const Mistake& mistake : c.mistakes) {
        double value = mistake.value[channel];
        bool matches = std::abs(m.mean - value) <= 4.0 * se + 0.01 * std::abs(value) + 1e-9;
        bool distinct = std::abs(value - c.expected[channel]) > 4.0 * se + 0.01 * std::abs(value) + 1e-9;
        if (matches && distinct) return ": it matches " + mistake.what + " (" + formatNumber(value) + ")";
    }
    return " (none of the common mistakes of docs/a6-radiometry.md gives this)";
}

// One case: the problem, or "". Deterministic estimates (no spread) must equal the closed form
// within float rounding (a wrong one is named by the mistake it matches), and are right only
// where the estimator has no spread either (a point light, nothing of the light in sight);
// random ones must pass the z test of their mean at
// `alpha`, be precise enough to judge (standard error at most 2 % of the answer), and spread as
// much as the estimator does: their variance against the estimator's, at `alpha` too, beyond the
// accuracy of the grader's quadrature.
std::string judgeCase(const EstimatorCase& c, const std::vector<Vec3>& samples, double alpha, std::vector<std::string>& details) {
    if (samples.size() != c.call.count) return std::to_string(samples.size()) + " samples for " + std::to_string(c.call.count);
    std::array<MeanEstimate, 3> means;
    for (size_t i = 0; i < samples.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            if (!std::isfinite(samples[i][ch])) return "sample " + std::to_string(i) + " is " + formatNumber(samples[i][ch]);
            means[ch].add(samples[i][ch]);
        }
    std::string line = c.id + " [" + c.inputs + "]: mean " + vec({means[0].mean, means[1].mean, means[2].mean}) + ", closed form " + vec(c.expected);
    if (means[0].standardError() > 0.0)
        line += ", z " + vec({(means[0].mean - c.expected.x) / means[0].standardError(), (means[1].mean - c.expected.y) / means[1].standardError(),
                              (means[2].mean - c.expected.z) / means[2].standardError()});
    line += "; variance " + vec({means[0].variance(), means[1].variance(), means[2].variance()}) + ", the estimator's " + vec(c.spread.variance);
    if (c.spread.variance.x > 0.0) {
        auto spreadZ = [&](int ch) {
            return (means[ch].variance() - c.spread.variance[ch]) / varianceStandardError(means[ch].count, c.spread.variance[ch], c.spread.fourthMoment[ch]);
        };
        line += ", z " + vec({spreadZ(0), spreadZ(1), spreadZ(2)});
    }
    details.push_back(line);
    for (int ch = 0; ch < 3; ++ch) {
        const MeanEstimate& m = means[ch];
        double expected = c.expected[ch], se = m.standardError(), variance = c.spread.variance[ch];
        std::string head = std::string(kChannels[ch]) + ": mean " + formatNumber(m.mean);
        if (se == 0.0) {
            std::string same = m.count > 1 ? " from every u" : "";
            if (!close(m.mean, expected, 1e-4) && std::abs(m.mean - expected) > 1e-7)
                return head + same + ", the closed form gives " + formatNumber(expected) + matchingMistake(c, ch, m);
            if (variance > 0.0)
                return head + same + ", where one sample of this estimator varies with u (standard deviation " + formatNumber(std::sqrt(variance)) +
                       "): an answer that does not depend on u is no Monte Carlo sample";
            continue;
        }
        double z = (m.mean - expected) / se;
        if (normalTwoSidedP(z) < alpha)
            return head + " +- " + formatNumber(se) + " where the closed form gives " + formatNumber(expected) + " (z = " + formatNumber(z) + ")" +
                   matchingMistake(c, ch, m);
        if (expected != 0.0 && se > 0.02 * std::abs(expected))
            return head + " +- " + formatNumber(se) + ": too noisy to judge (the standard error is over 2 % of " + formatNumber(expected) + ")";
        if (variance > 0.0) {
            double error = varianceStandardError(m.count, variance, c.spread.fourthMoment[ch]);
            double beyond = std::max(0.0, std::abs(m.variance() - variance) - kSpreadAccuracy * variance) / error;
            if (normalTwoSidedP(beyond) < alpha)
                return std::string(kChannels[ch]) + ": the samples' variance " + formatNumber(m.variance()) + " where one sample of this estimator has " +
                       formatNumber(variance) + " (z = " + formatNumber((m.variance() - variance) / error) +
                       "): a right mean with the wrong spread is not this estimator (one sample per u, with the pinned sampler)";
        }
    }
    return "";
}

TestGroup estimatorGroup(std::string test, const std::string& stub, std::shared_ptr<const std::vector<EstimatorCase>> cases) {
    TestGroup group{kA6, test, {estimatorPhase(stub, *cases)}, {}};
    group.score = [test, cases](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, test);
        if (!failedPhaseResult(run.phases[0], result)) scoreGuarded(result, [&] {
            // Sidak over every case's two tests, of its mean and of its spread. The three channels
            // of a case are one sample scaled by the albedo, with the same z.
            double alpha = sidakLevel(kAlpha, static_cast<int>(2 * cases->size()));
            ByteReader in(run.phases[0].data);
            CaseTally tally(result);
            std::vector<std::string> lines;
            for (const EstimatorCase& c : *cases)
                tally.record(c.id, judgeCase(c, in.getVector<Vec3>(worker::kMaxSamplesPerCall), alpha, lines));
            tally.finish();
            result.details.insert(result.details.end(), lines.begin(), lines.end());
        });
        results.push_back(std::move(result));
    };
    return group;
}

// Plain Monte Carlo: the RMS error of means of N independent samples falls as N^-1/2. Batches
// of N from one long run of the area estimator on case T1; the slope of log RMS against log N
// must be -0.5 +- 0.05.
TestGroup convergenceGroup(uint64_t seed) {
    auto c = std::make_shared<EstimatorCase>(triangleLightCases(Estimator::TriangleByArea, seed).front());
    c->call.count = worker::kMaxSamplesPerCall;
    TestGroup group{kA6, "a6 convergence of plain Monte Carlo", {estimatorPhase(kStubLightEstimators, {*c})}, {}};
    group.score = [c](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, "a6/estimators/convergence");
        if (!failedPhaseResult(run.phases[0], result)) scoreGuarded(result, [&] {
            ByteReader in(run.phases[0].data);
            std::vector<Vec3> samples = in.getVector<Vec3>(worker::kMaxSamplesPerCall);
            std::vector<double> sizes, rms;
            double exact = c->expected.y;
            for (size_t n : {16u, 64u, 256u, 1024u, 4096u}) {
                size_t batches = samples.size() / n;
                double sum = 0.0;
                for (size_t b = 0; b < batches; ++b) {
                    double mean = 0.0;
                    for (size_t i = b * n; i < (b + 1) * n; ++i) mean += samples[i].y;
                    mean /= static_cast<double>(n);
                    sum += (mean - exact) * (mean - exact);
                }
                sizes.push_back(static_cast<double>(n));
                rms.push_back(std::sqrt(sum / static_cast<double>(batches)));
                result.details.push_back("N = " + std::to_string(n) + ": RMS error " + formatNumber(rms.back()) + " over " +
                                         std::to_string(batches) + " means");
            }
            double slope = logLogSlope(sizes, rms);
            if (std::isfinite(slope) && std::abs(slope + 0.5) <= 0.05) {
                markPassed(result, "slope " + formatNumber(slope));
            } else {
                markFailed(result, "the RMS error of the area estimator (case T1, green) falls as N^" + formatNumber(slope) +
                                       "; plain Monte Carlo falls as N^-0.5 (+-0.05): an error that levels off is a bias, one that "
                                       "does not fall is no sampling at all");
            }
        });
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace

std::vector<TestGroup> a6Groups(GradingContext& context) {
    const uint64_t seed = context.seed;
    std::vector<TestGroup> groups{unitsGroup()};
    for (TestGroup& g : solidAngleGroups()) groups.push_back(std::move(g));
    for (SamplerTarget& t : directionTargets(seed)) groups.push_back(samplerGroup(std::make_shared<SamplerTarget>(std::move(t))));
    groups.push_back(samplerGroup(std::make_shared<SamplerTarget>(triangleTarget(seed))));
    groups.push_back(samplerGroup(std::make_shared<SamplerTarget>(sphericalTriangleTarget(seed))));
    groups.push_back(pdfConversionGroup());
    auto add = [&](std::string test, const std::string& stub, std::vector<EstimatorCase> cases) {
        groups.push_back(estimatorGroup(std::move(test), stub, std::make_shared<const std::vector<EstimatorCase>>(std::move(cases))));
    };
    add("a6/estimators/point-light", kStubLightEstimators, pointLightCases(seed));
    add("a6/estimators/triangle-area", kStubLightEstimators, triangleLightCases(Estimator::TriangleByArea, seed));
    add("a6/estimators/triangle-solid-angle", kStubLightEstimators, triangleLightCases(Estimator::TriangleBySolidAngle, seed));
    add("a6/estimators/sphere-area", kStubLightEstimators, sphereLightCases(Estimator::SphereByArea, seed));
    add("a6/estimators/sphere-solid-angle", kStubLightEstimators, sphereLightCases(Estimator::SphereBySolidAngle, seed));
    add("a6/estimators/uniform-hemisphere", kStubDirectionEstimators, directionCases(Estimator::UniformHemisphere, seed));
    add("a6/estimators/cosine-hemisphere", kStubDirectionEstimators, directionCases(Estimator::CosineHemisphere, seed));
    groups.push_back(convergenceGroup(seed));
    return groups;
}

}  // namespace rtlab::grader
