// Assignment a6: radiometry and Monte Carlo direct lighting (docs/a6-radiometry.md#how-the-grader-checks-it).
// Units and solid angles by truth tables derived by hand from the definitions; samplers by
// Pearson's chi-square test over exact expected counts (10^6 samples a run, alpha = 0.01 with
// Sidak's correction over a test's runs) and by the pdf they report; estimators by z tests of
// their means against closed forms (alpha = 0.01, Sidak over a test's cases and channels), a
// failing mean named by the common mistake it matches; plain Monte Carlo's convergence by the
// slope of its RMS error. The worker returns raw values and samples; every statistic is here.
#include "framework/oracle/closed_forms.h"
#include "grader/kit/accelerator_checks.h"
#include "grader/a6_radiometry/a6_tests.h"
#include "grader/a6_radiometry/radiometry_cases.h"
#include "grader/a6_radiometry/sampler_histograms.h"
#include "grader/wire/scene_codec.h"
#include "grader/kit/statistics.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"

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

// --- Truth tables: units, solid angles, the sphere integral, pdf conversion -------------------

struct ValueCase {
    std::string id;  // what the case is and how its answer follows from the definition
    double expected;
};

// One phase per table: the worker writes one f64 (or f32) per call, in order.
template <typename Call, typename Value = double>
TestGroup tableGroup(const char* title, const char* test, const std::string& stub, const char* task,
                     std::vector<std::pair<Call, ValueCase>> table, double tolerance = kTableTolerance) {
    std::vector<Call> calls;
    auto cases = std::make_shared<std::vector<ValueCase>>();
    for (auto& [call, c] : table) {
        calls.push_back(call);
        cases->push_back(c);
    }
    ByteWriter input;
    input.putVector(calls);
    TestGroup group{kA6, title, {makePhase(stub, task, std::move(input))}, {}};
    group.score = [test = std::string(test), cases, tolerance](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, test);
        if (!failedPhaseResult(run.phases[0], result)) {
            ByteReader in(run.phases[0].data);
            CaseTally tally(result);
            for (const ValueCase& c : *cases) {
                double got = in.get<Value>();
                tally.record(c.id, close(got, c.expected, tolerance) ? ""
                                                                     : "expected " + formatNumber(c.expected) + ", got " + formatNumber(got));
            }
            tally.finish();
        }
        results.push_back(std::move(result));
    };
    return group;
}

TestGroup unitsGroup() {
    using F = worker::UnitFunction;
    using C = worker::UnitCall;
    return tableGroup<C>("a6 units", "a6/units/conversions", kStubUnits, worker::kTaskUnits,
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
    return {tableGroup<C>("a6 solid angles of cones and spheres", "a6/solid-angle/cone-and-sphere", kStubSolidAngles, worker::kTaskSolidAngles, cones),
            tableGroup<C>("a6 solid angles of triangles", "a6/solid-angle/triangle", kStubSolidAngles, worker::kTaskSolidAngles, triangles),
            tableGroup<C>("a6 solid angles of rectangles", "a6/solid-angle/rectangle", kStubSolidAngles, worker::kTaskSolidAngles, rectangles),
            tableGroup<G>("a6 the integral of dOmega", "a6/solid-angle/sphere-integral", kStubSolidAngles, worker::kTaskSphereIntegrals, integrals)};
}

TestGroup pdfConversionGroup() {
    using C = worker::PdfCall;
    const double inf = std::numeric_limits<double>::infinity();
    return tableGroup<C, float>("a6 area to solid-angle pdf", "a6/samplers/area-to-solid-angle", kStubSamplers, worker::kTaskPdfConversions,
                                {
                                    {C{0.5f, 4.0f, 0.5f}, {"pdfArea 0.5, d^2 = 4, cos 0.5: 0.5 * 4 / 0.5", 4.0}},
                                    {C{0.25f, 9.0f, -0.75f}, {"cos -0.75 (the light's back): |cos|, 0.25 * 9 / 0.75", 3.0}},
                                    {C{2.0f, 1.0f, 1.0f}, {"facing the point at distance 1: unchanged", 2.0}},
                                    {C{1.0f, 1.0f, 0.0f}, {"a grazing light point: infinite", inf}},
                                },
                                1e-6);
}

// --- Samplers: chi-square and the pdf --------------------------------------------------------

// What one sampler's runs are judged against.
struct SamplerTarget {
    std::string test;
    std::string stub;
    std::vector<worker::SamplerCall> runs;
    bool directions = true;  // unit vectors (else points of a triangle)
    // Per run: the histogram cell of a sample and the expected count of every cell.
    std::function<size_t(size_t run, const Vec3& value)> cellOf;
    std::function<std::vector<double>(size_t run)> expected;
    std::function<std::string(size_t run, size_t cell)> describe;
    // The density of a sample, and how the contract writes it.
    std::function<double(size_t run, const Vec3& value)> pdf;
    std::string pdfFormula;
};

// Every sampler's runs draw their own numbers: seed 1000 (sampler + 1) + run.
worker::SamplerCall samplerCall(Sampler sampler, size_t run) {
    worker::SamplerCall c{};
    c.sampler = sampler;
    c.seed = 1000 * (static_cast<uint64_t>(sampler) + 1) + run;
    c.count = kSamplesPerRun;
    return c;
}

// Directions with a distribution uniform in phi and F for z on [zMin, 1].
SamplerTarget directionTarget(std::string test, Sampler sampler, std::vector<float> conesOrNone, std::function<double(float, double)> zCdf,
                              std::function<double(float, const Vec3&)> pdf, std::string formula) {
    SamplerTarget t;
    t.test = std::move(test);
    t.stub = kStubSamplers;
    for (size_t run = 0; run < conesOrNone.size(); ++run) {
        worker::SamplerCall c = samplerCall(sampler, run);
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

std::vector<SamplerTarget> directionTargets() {
    const std::vector<float> three(3, 0.0f);
    return {
        directionTarget("a6/samplers/uniform-sphere", Sampler::UniformSphere, three, [](float, double z) { return (z + 1.0) / 2.0; },
                        [](float, const Vec3&) { return 1.0 / (4.0 * kPi); }, "1/(4 pi)"),
        directionTarget("a6/samplers/uniform-hemisphere", Sampler::UniformHemisphere, three, [](float, double z) { return z; },
                        [](float, const Vec3&) { return 1.0 / (2.0 * kPi); }, "1/(2 pi)"),
        directionTarget("a6/samplers/cosine-hemisphere", Sampler::CosineHemisphere, three, [](float, double z) { return z * z; },
                        [](float, const Vec3& v) { return v.z / kPi; }, "cos(theta)/pi"),
        directionTarget("a6/samplers/uniform-cone", Sampler::UniformCone, {0.9f, 0.2f, -0.5f},
                        [](float c, double z) { return (z - c) / (1.0 - c); },
                        [](float c, const Vec3&) { return 1.0 / (2.0 * kPi * (1.0 - double(c))); }, "1/(2 pi (1 - cosThetaMax))"),
    };
}

SamplerTarget triangleTarget() {
    struct Run {
        DVec3 p0, p1, p2;
    };
    std::vector<Run> triangles{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                               {{-1, 2, 0.5}, {3, 2.5, -1}, {0.5, -1, 2}},
                               {{100, 100, 100}, {100.5, 100, 100}, {100, 100.01, 100.3}}};
    SamplerTarget t;
    t.test = "a6/samplers/uniform-triangle";
    t.stub = kStubSamplers;
    t.directions = false;
    for (size_t run = 0; run < triangles.size(); ++run) {
        worker::SamplerCall c = samplerCall(Sampler::UniformTriangle, run);
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

SamplerTarget sphericalTriangleTarget() {
    struct Run {
        DVec3 p, p0, p1, p2;
    };
    std::vector<Run> configurations{{{0, 0, 0}, {-0.5, -0.4, 1}, {0.1, 0.7, 0.9}, {0.6, -0.3, 1.2}},
                                    {{0.2, 0.1, 0.05}, {-3, -3, 0.3}, {3, -3, 0.3}, {0, 4, 0.3}},
                                    {{0, 0, 0}, {4, 0.1, 0.2}, {4, 0.3, 0.1}, {4.2, 0.2, 0.3}}};
    SamplerTarget t;
    t.test = "a6/samplers/spherical-triangle";
    t.stub = kStubSphericalTriangle;
    for (size_t run = 0; run < configurations.size(); ++run) {
        worker::SamplerCall c = samplerCall(Sampler::SphericalTriangle, run);
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

// The problems of one run, or "" when it passes at level `alpha`.
std::string judgeRun(const SamplerTarget& t, size_t run, const std::vector<worker::SampleResult>& samples, double alpha,
                     std::vector<std::string>& details) {
    std::string tag = "run " + std::to_string(run + 1);
    if (samples.size() != t.runs[run].count) return tag + ": " + std::to_string(samples.size()) + " samples for " + std::to_string(t.runs[run].count);
    std::vector<double> observed(t.expected(run).size(), 0.0);
    for (size_t i = 0; i < samples.size(); ++i) {
        const Vec3& v = samples[i].value;
        std::string where = tag + ", sample " + std::to_string(i) + " " + vec(DVec3(v));
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(samples[i].pdf))
            return where + ": not finite (pdf " + formatNumber(samples[i].pdf) + ")";
        if (t.directions && std::abs(glm::length(DVec3(v)) - 1.0) > 1e-4) return where + ": not of unit length";
        double density = t.pdf(run, v);
        if (std::abs(samples[i].pdf - density) > 1e-3 * density + 1e-6)
            return where + ": pdf " + formatNumber(samples[i].pdf) + ", but the density of this sample is " + t.pdfFormula + " = " +
                   formatNumber(density) + " (the pdf must be the one of the sample returned)";
        observed[t.cellOf(run, v)] += 1.0;
    }
    std::vector<double> expected = t.expected(run);
    ChiSquareResult chi = chiSquareTest(observed, expected);
    size_t worst = chi.worstCell;
    details.push_back(tag + ": chi^2 = " + formatNumber(chi.chiSquare) + " with " + std::to_string(chi.dof) + " degrees of freedom, p = " +
                      formatNumber(chi.p) + " (" + std::to_string(chi.pooledCells) + " cells pooled); most off: " + t.describe(run, worst) +
                      ", " + formatNumber(observed[worst]) + " samples for " + formatNumber(expected[worst]) + " expected");
    if (chi.outsideObserved > 0)
        return tag + ": " + formatNumber(chi.outsideObserved) + " of " + std::to_string(samples.size()) + " samples " +
               t.describe(run, observed.size() - 1) + ", where the density is 0";
    if (!(chi.p >= alpha))
        return tag + ": the samples do not follow the distribution (chi^2 = " + formatNumber(chi.chiSquare) + ", " + std::to_string(chi.dof) +
               " degrees of freedom, p = " + formatNumber(chi.p) + " < " + formatNumber(alpha) + "); most off: " + t.describe(run, worst) +
               ", " + formatNumber(observed[worst]) + " samples for " + formatNumber(expected[worst]) + " expected";
    return "";
}

TestGroup samplerGroup(std::shared_ptr<const SamplerTarget> t) {
    TestGroup group;
    group.assignment = kA6;
    group.title = t->test;
    for (const worker::SamplerCall& call : t->runs) {
        ByteWriter input;
        input.put(call);
        group.phases.push_back(makePhase(t->stub, worker::kTaskSamples, std::move(input)));
    }
    group.score = [t](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, t->test);
        // Sidak over the runs: the family keeps alpha = 0.01.
        double alpha = sidakLevel(kAlpha, static_cast<int>(t->runs.size()));
        CaseTally tally(result);
        for (size_t k = 0; k < t->runs.size(); ++k) {
            if (failedPhaseResult(run.phases[k], result)) {
                results.push_back(std::move(result));
                return;
            }
            ByteReader in(run.phases[k].data);
            std::vector<std::string> details;
            std::string problem = judgeRun(*t, k, in.getVector<worker::SampleResult>(worker::kMaxSamplesPerCall), alpha, details);
            result.details.insert(result.details.end(), details.begin(), details.end());
            tally.record("run " + std::to_string(k + 1), problem.empty() ? "" : problem.substr(problem.find(": ") + 2));
        }
        tally.finish();
        results.push_back(std::move(result));
    };
    return group;
}

// --- Estimators: z tests and the mistakes they match -----------------------------------------

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
// within float rounding; random ones must pass the z test at `alpha` and be precise enough to
// judge (standard error at most 2 % of the answer).
std::string judgeCase(const EstimatorCase& c, const std::vector<Vec3>& samples, double alpha, std::vector<std::string>& details) {
    if (samples.size() != c.call.count) return std::to_string(samples.size()) + " samples for " + std::to_string(c.call.count);
    std::array<MeanEstimate, 3> means;
    for (size_t i = 0; i < samples.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            if (!std::isfinite(samples[i][ch])) return "sample " + std::to_string(i) + " is " + formatNumber(samples[i][ch]);
            means[ch].add(samples[i][ch]);
        }
    std::string line = c.id + ": mean " + vec({means[0].mean, means[1].mean, means[2].mean}) + ", closed form " + vec(c.expected);
    if (means[0].standardError() > 0.0)
        line += ", z " + vec({(means[0].mean - c.expected.x) / means[0].standardError(), (means[1].mean - c.expected.y) / means[1].standardError(),
                              (means[2].mean - c.expected.z) / means[2].standardError()});
    details.push_back(line);
    for (int ch = 0; ch < 3; ++ch) {
        const MeanEstimate& m = means[ch];
        double expected = c.expected[ch], se = m.standardError();
        std::string head = std::string(kChannels[ch]) + ": mean " + formatNumber(m.mean);
        if (se == 0.0) {
            if (!close(m.mean, expected, 1e-4) && std::abs(m.mean - expected) > 1e-7)
                return head + ", the closed form gives " + formatNumber(expected) + matchingMistake(c, ch, m);
            continue;
        }
        double z = (m.mean - expected) / se;
        if (normalTwoSidedP(z) < alpha)
            return head + " +- " + formatNumber(se) + " where the closed form gives " + formatNumber(expected) + " (z = " + formatNumber(z) + ")" +
                   matchingMistake(c, ch, m);
        if (expected != 0.0 && se > 0.02 * std::abs(expected))
            return head + " +- " + formatNumber(se) + ": too noisy to judge (the standard error is over 2 % of " + formatNumber(expected) + ")";
    }
    return "";
}

TestGroup estimatorGroup(std::string test, const std::string& stub, std::shared_ptr<const std::vector<EstimatorCase>> cases) {
    TestGroup group{kA6, test, {estimatorPhase(stub, *cases)}, {}};
    group.score = [test, cases](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, test);
        if (!failedPhaseResult(run.phases[0], result)) {
            // Sidak over every case's three channels.
            double alpha = sidakLevel(kAlpha, static_cast<int>(3 * cases->size()));
            ByteReader in(run.phases[0].data);
            CaseTally tally(result);
            std::vector<std::string> lines;
            for (const EstimatorCase& c : *cases)
                tally.record(c.id, judgeCase(c, in.getVector<Vec3>(worker::kMaxSamplesPerCall), alpha, lines));
            tally.finish();
            result.details.insert(result.details.end(), lines.begin(), lines.end());
        }
        results.push_back(std::move(result));
    };
    return group;
}

// Plain Monte Carlo: the RMS error of means of N independent samples falls as N^-1/2. Batches
// of N from one long run of the area estimator on case T1; the slope of log RMS against log N
// must be -0.5 +- 0.05.
TestGroup convergenceGroup() {
    auto c = std::make_shared<EstimatorCase>(triangleLightCases(Estimator::TriangleByArea).front());
    c->call.count = worker::kMaxSamplesPerCall;
    TestGroup group{kA6, "a6 convergence of plain Monte Carlo", {estimatorPhase(kStubLightEstimators, {*c})}, {}};
    group.score = [c](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA6, "a6/estimators/convergence");
        if (!failedPhaseResult(run.phases[0], result)) {
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
        }
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace

std::vector<TestGroup> a6Groups(GradingContext&) {
    std::vector<TestGroup> groups{unitsGroup()};
    for (TestGroup& g : solidAngleGroups()) groups.push_back(std::move(g));
    for (SamplerTarget& t : directionTargets()) groups.push_back(samplerGroup(std::make_shared<SamplerTarget>(std::move(t))));
    groups.push_back(samplerGroup(std::make_shared<SamplerTarget>(triangleTarget())));
    groups.push_back(samplerGroup(std::make_shared<SamplerTarget>(sphericalTriangleTarget())));
    groups.push_back(pdfConversionGroup());
    auto add = [&](std::string test, const std::string& stub, std::vector<EstimatorCase> cases) {
        groups.push_back(estimatorGroup(std::move(test), stub, std::make_shared<const std::vector<EstimatorCase>>(std::move(cases))));
    };
    add("a6/estimators/point-light", kStubLightEstimators, pointLightCases());
    add("a6/estimators/triangle-area", kStubLightEstimators, triangleLightCases(Estimator::TriangleByArea));
    add("a6/estimators/triangle-solid-angle", kStubLightEstimators, triangleLightCases(Estimator::TriangleBySolidAngle));
    add("a6/estimators/sphere-area", kStubLightEstimators, sphereLightCases(Estimator::SphereByArea));
    add("a6/estimators/sphere-solid-angle", kStubLightEstimators, sphereLightCases(Estimator::SphereBySolidAngle));
    add("a6/estimators/uniform-hemisphere", kStubDirectionEstimators, directionCases(Estimator::UniformHemisphere));
    add("a6/estimators/cosine-hemisphere", kStubDirectionEstimators, directionCases(Estimator::CosineHemisphere));
    groups.push_back(convergenceGroup());
    return groups;
}

}  // namespace rtlab::grader
