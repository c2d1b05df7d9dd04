// Assignment a0: the slab, triangle and sphere tests, on the stress catalogue's exact cases
// and on randomized property tests with known answers.
#include "framework/core/pcg32.h"
#include "framework/interface/a0_intersect.h"
#include "grader/a0_intersect/a0_tests.h"
#include "grader/kit/hit_judge.h"
#include "grader/kit/stress_cases.h"
#include "grader/kit/test_scenes.h"
#include "grader/kit/truth_table.h"
#include "grader/a0_intersect/wire/intersection_inputs.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <span>

namespace rtlab::grader {
namespace {

// The stubs named in verdicts ("crashed with SIGSEGV in <stub>").
const std::string kStubBox = a0Stubs().name("intersectBox");
const std::string kStubTriangle = a0Stubs().name("intersectTriangle");
const std::string kStubSphere = a0Stubs().name("intersectSphere");

constexpr const char* kA0 = "a0";

std::string formatFloat(double v) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.9g", v);
    return buffer;
}

std::string boxShape(const Bounds3f& box) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "box (%.9g, %.9g, %.9g)-(%.9g, %.9g, %.9g)", box.lower.x, box.lower.y, box.lower.z,
                  box.upper.x, box.upper.y, box.upper.z);
    return buffer;
}

std::string describeSphere(const Vec3& centre, float radius) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "sphere centre (%.9g, %.9g, %.9g) radius %.9g", centre.x, centre.y, centre.z, radius);
    return buffer;
}

std::string describeTriangle(const std::array<Vec3, 3>& v) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g)", v[0].x, v[0].y, v[0].z,
                  v[1].x, v[1].y, v[1].z, v[2].x, v[2].y, v[2].z);
    return buffer;
}

bool closeTo(double value, double expected, double relative) {
    return std::abs(value - expected) <= relative * std::max(1.0, std::abs(expected));
}

// One ray case of a truth table: the detail line names the shape too (what --verbose and the
// HTML report show, so a failing case can be reproduced from the line alone); the reason keeps
// the shorter id, ray and problem.
CaseLine rayCaseLine(const std::string& id, const std::string& shape, const Ray& ray, const std::string& problem) {
    return {problem.empty(), id + " " + shape + ", ray " + describeRay(ray) + ": " + problem, id + " " + describeRay(ray) + ": " + problem};
}

// --- Truth tables ---------------------------------------------------------------------------

// A phase that runs `task` on every query: the box, triangle and sphere tables share it.
template <typename Query>
ChildPhase queriesPhase(const std::string& stub, const char* task, const std::vector<Query>& queries) {
    ByteWriter input;
    input.putVector(queries);
    return makePhase(stub, task, std::move(input));
}

ChildPhase boxTablePhase(std::shared_ptr<const std::vector<BoxCase>> cases) {
    return tablePhase(kStubBox, worker::kTaskBox, *cases, [](const BoxCase& c) { return worker::BoxQuery{c.box, c.ray}; });
}

void scoreBoxTable(const std::vector<BoxCase>& cases, const PhaseOutcome& outcome, TestResult& result) {
    scoreTable(outcome, cases, result, [](const BoxCase& c, ByteReader& in) {
        bool hit = in.get<uint8_t>() != 0;
        float enter = in.get<float>();
        std::string problem;
        if (hit != c.hit) problem = std::string("expected ") + (c.hit ? "hit" : "miss") + ", got " + (hit ? "hit" : "miss");
        else if (hit && !closeTo(enter, c.enter, 1e-5)) problem = "expected tEnter " + formatFloat(c.enter) + ", got " + formatFloat(enter);
        return rayCaseLine(c.id, boxShape(c.box), c.ray, problem);
    });
}

ChildPhase trianglePhase(const std::vector<worker::TriangleQuery>& queries) {
    return queriesPhase(kStubTriangle, worker::kTaskTriangle, queries);
}

// Every triangle of every case, each with its case's ray.
ChildPhase triangleTablePhase(std::shared_ptr<const std::vector<TriangleCase>> cases) {
    std::vector<worker::TriangleQuery> queries;
    for (const TriangleCase& c : *cases)
        for (const auto& v : c.triangles) queries.push_back({c.ray, v[0], v[1], v[2]});
    return trianglePhase(queries);
}

void scoreTriangleTable(const std::vector<TriangleCase>& cases, const PhaseOutcome& outcome, TestResult& result) {
    scoreTable(outcome, cases, result, [](const TriangleCase& c, ByteReader& in) {
        bool anyHit = false;
        std::string problem;
        for (size_t k = 0; k < c.triangles.size(); ++k) {
            bool hit = in.get<uint8_t>() != 0;
            float t = in.get<float>();
            if (!hit) continue;
            anyHit = true;
            if (!c.hit) problem = "expected a miss, got a hit on triangle " + std::to_string(k) + " at t=" + formatFloat(t);
            else if (!closeTo(t, c.t, c.tolerance) && problem.empty())
                problem = "expected t=" + formatFloat(c.t) + ", got t=" + formatFloat(t) + " on triangle " + std::to_string(k);
        }
        if (c.hit && !anyHit) problem = "expected a hit at t=" + formatFloat(c.t) + ", got a miss";
        std::string shapes;
        for (size_t k = 0; k < c.triangles.size(); ++k)
            shapes += (k ? "; " : "") + std::string("triangle ") + std::to_string(k) + " " + describeTriangle(c.triangles[k]);
        return rayCaseLine(c.id, shapes, c.ray, problem);
    });
}

ChildPhase sphereTablePhase(std::shared_ptr<const std::vector<SphereCase>> cases) {
    return tablePhase(kStubSphere, worker::kTaskSphere, *cases, [](const SphereCase& c) { return worker::SphereQuery{c.ray, c.centre, c.radius}; });
}

void scoreSphereTable(const std::vector<SphereCase>& cases, const PhaseOutcome& outcome, TestResult& result) {
    scoreTable(outcome, cases, result, [](const SphereCase& c, ByteReader& in) {
        bool hit = in.get<uint8_t>() != 0;
        float t = in.get<float>();
        std::string problem;
        if (hit != c.hit) problem = std::string("expected ") + (c.hit ? "a hit at t=" + formatFloat(c.t) : "a miss") + ", got " + (hit ? "a hit at t=" + formatFloat(t) : "a miss");
        else if (hit && !closeTo(t, c.t, c.tolerance)) problem = "expected t=" + formatFloat(c.t) + ", got t=" + formatFloat(t);
        return rayCaseLine(c.id, describeSphere(c.centre, c.radius), c.ray, problem);
    });
}

template <typename Case>
std::shared_ptr<const std::vector<Case>> select(const std::vector<Case>& all, std::initializer_list<const char*> prefixes) {
    auto chosen = std::make_shared<std::vector<Case>>();
    for (const Case& c : all)
        for (const char* prefix : prefixes)
            if (c.id.rfind(prefix, 0) == 0) {
                chosen->push_back(c);
                break;
            }
    return chosen;
}

// --- Property tests ---------------------------------------------------------------------------

// Counts wrong cases and keeps the first few as report lines.
struct Tally {
    size_t total = 0, wrong = 0;
    std::vector<std::string> examples;
    void fail(const std::string& line) {
        ++wrong;
        if (examples.size() < 5) examples.push_back(line);
    }
    void into(TestResult& result, const std::string& what) const {
        result.details.insert(result.details.end(), examples.begin(), examples.end());
        result.fraction = wrong == 0 ? 1.0 : 0.0;
        result.status = wrong == 0 ? TestStatus::Passed : TestStatus::Failed;
        result.reason = wrong == 0 ? "" : std::to_string(wrong) + " of " + std::to_string(total) + " " + what + "; first: " + examples.front();
        result.details.insert(result.details.begin(), std::to_string(total) + " cases, " + std::to_string(wrong) + " wrong");
    }
};

// BOX-05 (Ize): rays through the shared edge y = 0 of two flat boxes at z = 5. A box the ray
// touches in double precision must be hit; which one is decided by rounding, both may be.
struct IzeRays {
    Bounds3f boxes[2] = {Bounds3f({0, 0, 5}, {1, 1, 5}), Bounds3f({0, -1, 5}, {1, 0, 5})};
    std::vector<Ray> rays;
};

// Every ray against both boxes, ray by ray; the entry distance is not judged.
ChildPhase izePhase(const IzeRays& ize) {
    ByteWriter input;
    input.putVector(std::span<const Bounds3f>(ize.boxes));
    input.putVector(ize.rays);
    return makePhase(kStubBox, worker::kTaskRaysAgainstBoxes, std::move(input));
}

bool exactSlab(const Bounds3f& box, const Ray& ray) {
    double t0 = ray.tMin, t1 = ray.tMax;
    for (int axis = 0; axis < 3; ++axis) {
        double inv = 1.0 / double(ray.direction[axis]);
        double lo = (double(box.lower[axis]) - ray.origin[axis]) * inv, hi = (double(box.upper[axis]) - ray.origin[axis]) * inv;
        if (std::signbit(inv)) std::swap(lo, hi);
        t0 = lo > t0 ? lo : t0;
        t1 = hi < t1 ? hi : t1;
    }
    return t0 <= t1;
}

TestGroup slabGroup(uint64_t seed) {
    auto all = boxCases();
    auto facePlanes = select(all, {"BOX-01"});
    auto flat = select(all, {"BOX-02", "BOX-03"});
    auto interval = select(all, {"BOX-06"});
    auto ize = std::make_shared<IzeRays>();
    Pcg32 rng(seed, 21);
    for (int i = 0; i < 100000; ++i) {
        float xh = 0.05f + 0.9f * rng.uniform(), u = 2 * rng.uniform() - 1;
        Vec3 d(u, u, 1.05f + 0.9f * rng.uniform());
        ize->rays.push_back(makeRay(Vec3(xh, 0, 5) - d, d));
    }
    TestGroup group;
    group.assignment = kA0;
    group.title = "a0 slab test";
    group.phases = {noSetUp(), boxTablePhase(facePlanes), boxTablePhase(flat), boxTablePhase(interval),
                    izePhase(*ize)};
    group.score = [=](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult a = makeResult(kA0, "a0/slab/face-planes");
        scoreBoxTable(*facePlanes, run.phases[1], a);
        TestResult b = makeResult(kA0, "a0/slab/flat-boxes");
        scoreBoxTable(*flat, run.phases[2], b);
        TestResult c = makeResult(kA0, "a0/slab/interval");
        scoreBoxTable(*interval, run.phases[3], c);
        TestResult d = makeResult(kA0, "a0/slab/shared-edge-property");
        if (!failedPhaseResult(run.phases[4], d)) {
            ByteReader in(run.phases[4].data);
            Tally tally;
            for (const Ray& ray : ize->rays)
                for (const Bounds3f& box : ize->boxes) {
                    bool hit = in.get<uint8_t>() != 0;
                    in.get<float>();
                    ++tally.total;
                    if (!hit && exactSlab(box, ray))
                        tally.fail("BOX-05 " + boxShape(box) + ", ray " + describeRay(ray) +
                                   ": expected a hit (the ray touches the flat box at z = 5), got a miss");
                }
            tally.into(d, "box tests lost a box the ray touches");
        }
        for (TestResult* r : {&a, &b, &c, &d}) results.push_back(std::move(*r));
    };
    return group;
}

// TRI-03: rays through the shared edge BC of two triangles (coplanar, and folded by 0.3 n).
struct SharedEdgeCase {
    std::array<Vec3, 3> first, second;  // (A, B, C) and (C, B, D)
    Ray ray;
};

std::vector<SharedEdgeCase> sharedEdgeCases(uint64_t seed, int count) {
    Pcg32 rng(seed, 31);
    auto u = [&] { return 2 * rng.uniform() - 1; };
    std::vector<SharedEdgeCase> cases;
    while (int(cases.size()) < count) {
        Vec3 a(u(), u(), u()), b(u(), u(), u()), c(u(), u(), u());
        Vec3 d = b + c - a;
        Vec3 n = glm::cross(b - a, c - a);
        if (!(glm::length(n) > 1e-3f)) continue;
        if (cases.size() % 2) d += 0.3f * glm::normalize(n);
        Vec3 p = b + (0.001f + 0.998f * rng.uniform()) * (c - b);
        Vec3 o(3 * u(), 3 * u(), 4 + 3 * u());
        Vec3 dir = p - o;
        // Silhouette (A and D on the same side of the plane through o, B, C) and grazing rays
        // are discarded: there a miss of both is legitimate.
        DVec3 plane = glm::cross(DVec3(b) - DVec3(o), DVec3(c) - DVec3(o));
        if (glm::dot(plane, DVec3(a) - DVec3(o)) * glm::dot(plane, DVec3(d) - DVec3(o)) >= 0) continue;
        if (std::abs(glm::dot(glm::normalize(n), glm::normalize(dir))) < 1e-3f) continue;
        cases.push_back({{a, b, c}, {c, b, d}, makeRay(o, dir)});
    }
    return cases;
}

// TRI-04: from inside a closed icosphere towards points on its edges and its vertices.
struct LeakRays {
    TestScene sphere = icosphere(2);
    std::vector<Ray> rays;
};

std::shared_ptr<LeakRays> leakRays(uint64_t seed, int count) {
    auto leak = std::make_shared<LeakRays>();
    const Scene& s = leak->sphere.scene;
    Pcg32 rng(seed, 41);
    for (int i = 0; i < count; ++i) {
        auto v = s.triangleVertices(rng.next() % s.triangleCount());
        int e = int(rng.next() % 3);
        Vec3 target = i % 2 ? v[e] : v[e] + (0.001f + 0.998f * rng.uniform()) * (v[(e + 1) % 3] - v[e]);
        leak->rays.push_back(makeRay(leak->sphere.inside, target - leak->sphere.inside));
    }
    return leak;
}

// Large coordinates: triangles near S = 2^10 .. 2^22 with vertices on the float grid there,
// rays towards a grid point well inside; every ray must hit, at the t computed in double from
// the (exactly representable) inputs.
struct OffsetCase {
    std::array<Vec3, 3> triangle;
    Ray ray;
    double t;
};

std::vector<OffsetCase> largeOffsetCases(uint64_t seed, int count) {
    Pcg32 rng(seed, 51);
    std::vector<OffsetCase> cases;
    const float scales[] = {1024.0f, 65536.0f, 1048576.0f, 4194304.0f};
    while (int(cases.size()) < count) {
        float s = scales[cases.size() % 4];
        float q = s * 0x1p-23f;  // one ulp at s
        auto grid = [&](int range) { return float(int(rng.next() % uint32_t(2 * range + 1)) - range) * q; };
        Vec3 base(s);
        std::array<Vec3, 3> v = {base + Vec3(grid(256), grid(256), grid(256)), base + Vec3(grid(256), grid(256), grid(256)),
                                 base + Vec3(grid(256), grid(256), grid(256))};
        double b1 = 0.15 + 0.3 * rng.uniform(), b2 = 0.15 + 0.3 * rng.uniform();
        DVec3 pd = (1 - b1 - b2) * DVec3(v[0]) + b1 * DVec3(v[1]) + b2 * DVec3(v[2]);
        Vec3 p(std::round(pd.x / q) * q, std::round(pd.y / q) * q, std::round(pd.z / q) * q);
        Vec3 o = p + Vec3(grid(1000), grid(1000), grid(1000) + 3000 * q);
        DVec3 n = glm::cross(DVec3(v[1]) - DVec3(v[0]), DVec3(v[2]) - DVec3(v[0]));
        DVec3 dir = DVec3(p) - DVec3(o);
        if (glm::length(n) < 1000.0 * q * q || std::abs(glm::dot(glm::normalize(n), glm::normalize(dir))) < 0.05) continue;
        // p was rounded to the grid, off the plane: where the ray meets the plane must be well
        // inside the triangle.
        Ray ray = makeRay(o, p - o);
        double t = glm::dot(n, DVec3(v[0]) - DVec3(o)) / glm::dot(n, DVec3(ray.direction));
        DVec3 x = DVec3(o) + t * DVec3(ray.direction);
        double area2 = glm::dot(n, n);
        bool inside = true;
        for (int k = 0; k < 3; ++k)
            inside &= glm::dot(glm::cross(DVec3(v[(k + 1) % 3]) - DVec3(v[k]), x - DVec3(v[k])), n) >= 0.05 * area2;
        if (!inside) continue;
        cases.push_back({v, ray, t});
    }
    return cases;
}

ChildPhase sharedEdgePhase(const std::vector<SharedEdgeCase>& cases) {
    std::vector<worker::TriangleQuery> queries;
    for (const SharedEdgeCase& c : cases)
        for (const auto* v : {&c.first, &c.second}) queries.push_back({c.ray, (*v)[0], (*v)[1], (*v)[2]});
    return trianglePhase(queries);
}

// The nearest hit over the whole icosphere per ray, as a traversal would find it.
ChildPhase leakPhase(const LeakRays& leak) {
    const Scene& s = leak.sphere.scene;
    std::vector<std::array<Vec3, 3>> triangles;
    for (uint32_t prim = 0; prim < s.triangleCount(); ++prim) triangles.push_back(s.triangleVertices(prim));
    ByteWriter input;
    input.putVector(triangles);
    input.putVector(leak.rays);
    return makePhase(kStubTriangle, worker::kTaskClosestTriangle, std::move(input));
}

ChildPhase offsetPhase(const std::vector<OffsetCase>& cases) {
    std::vector<worker::TriangleQuery> queries;
    for (const OffsetCase& c : cases) queries.push_back({c.ray, c.triangle[0], c.triangle[1], c.triangle[2]});
    return trianglePhase(queries);
}

TestGroup triangleGroup(uint64_t seed) {
    auto all = triangleCases();
    auto regressions = select(all, {"TRI-01", "TRI-02"});
    auto edges = select(all, {"TRI-05", "TRI-06", "TRI-07", "TRI-08"});
    auto degenerate = select(all, {"TRI-11", "TRI-12", "TRI-13", "TRI-14"});
    auto boundary = select(all, {"TRI-15"});
    auto big = select(all, {"BIG-01"});
    auto shared = std::make_shared<std::vector<SharedEdgeCase>>(sharedEdgeCases(seed, 20000));
    auto leak = leakRays(seed, 20000);
    auto offsets = std::make_shared<std::vector<OffsetCase>>(largeOffsetCases(seed, 4000));

    TestGroup group;
    group.assignment = kA0;
    group.title = "a0 triangle test";
    group.phases = {noSetUp(), triangleTablePhase(regressions), triangleTablePhase(edges), triangleTablePhase(degenerate),
                    triangleTablePhase(boundary),
                    sharedEdgePhase(*shared), leakPhase(*leak), offsetPhase(*offsets),
                    triangleTablePhase(big)};
    group.score = [=](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult r1 = makeResult(kA0, "a0/triangle/shared-edge-regressions");
        scoreTriangleTable(*regressions, run.phases[1], r1);
        TestResult r2 = makeResult(kA0, "a0/triangle/edges-and-winding");
        scoreTriangleTable(*edges, run.phases[2], r2);
        TestResult r3 = makeResult(kA0, "a0/triangle/degenerate-and-nan");
        scoreTriangleTable(*degenerate, run.phases[3], r3);
        TestResult r4 = makeResult(kA0, "a0/triangle/boundary-t");
        scoreTriangleTable(*boundary, run.phases[4], r4);

        TestResult r5 = makeResult(kA0, "a0/triangle/shared-edge-property");
        if (!failedPhaseResult(run.phases[5], r5)) {
            ByteReader in(run.phases[5].data);
            Tally tally;
            for (const SharedEdgeCase& c : *shared) {
                ++tally.total;
                bool anyHit = false;
                std::string badT;
                for (int k = 0; k < 2; ++k) {
                    bool hit = in.get<uint8_t>() != 0;
                    float t = in.get<float>();
                    anyHit |= hit;
                    if (hit && std::abs(t - 1.0f) > 1e-4f) badT = "hit at t=" + formatFloat(t) + ", expected t=1";
                }
                std::string where = "TRI-03 triangles " + describeTriangle(c.first) + " and " + describeTriangle(c.second) +
                                    ", ray " + describeRay(c.ray);
                if (!anyHit) tally.fail(where + ": expected a hit on one of the two triangles sharing the edge, got two misses");
                else if (!badT.empty()) tally.fail(where + ": " + badT);
            }
            tally.into(r5, "rays through a shared edge leaked");
        }

        TestResult r6 = makeResult(kA0, "a0/triangle/closed-mesh-leaks");
        if (!failedPhaseResult(run.phases[6], r6)) {
            ByteReader in(run.phases[6].data);
            Tally tally;
            for (const Ray& ray : leak->rays) {
                ++tally.total;
                float t = in.get<float>();
                if (!(std::abs(t - 1.0f) <= 1e-4f))
                    tally.fail("TRI-04 " + describeRay(ray) + ": from inside the closed icosphere, expected a hit at t=1, got " +
                               (std::isfinite(t) ? "t=" + formatFloat(t) : std::string("a miss")));
            }
            tally.into(r6, "rays leaked out of a closed mesh");
        }

        TestResult r7 = makeResult(kA0, "a0/triangle/large-coordinates");
        if (!failedPhaseResult(run.phases[7], r7) && !failedPhaseResult(run.phases[8], r7)) {
            ByteReader in(run.phases[7].data);
            Tally tally;
            for (const OffsetCase& c : *offsets) {
                ++tally.total;
                bool hit = in.get<uint8_t>() != 0;
                float t = in.get<float>();
                if (!hit || !closeTo(t, c.t, 1e-5))
                    tally.fail("triangle " + describeTriangle(c.triangle) + ", " + describeRay(c.ray) + ": expected a hit at t=" +
                               formatFloat(c.t) + ", got " +
                               (hit ? "t=" + formatFloat(t) : std::string("a miss")));
            }
            TestResult bigTable = makeResult(kA0, "BIG-01");
            scoreTriangleTable(*big, run.phases[8], bigTable);
            if (bigTable.status != TestStatus::Passed) {
                ++tally.total;
                // A phase that did not complete, or sent a malformed record, leaves no detail line.
                tally.fail(bigTable.details.empty() ? bigTable.reason : bigTable.details.front());
            } else {
                ++tally.total;
            }
            tally.into(r7, "large-coordinate rays were wrong");
        }
        for (TestResult* r : {&r1, &r2, &r3, &r4, &r5, &r6, &r7}) results.push_back(std::move(*r));
    };
    return group;
}

// Random spheres (also far from the origin) and rays with robust answers, judged in double.
struct SphereProperty {
    std::vector<SphereCase> cases;
};

std::shared_ptr<SphereProperty> sphereProperty(uint64_t seed, int count) {
    auto property = std::make_shared<SphereProperty>();
    Pcg32 rng(seed, 61);
    const float offsets[] = {0.0f, 1000.0f, 100000.0f};
    while (int(property->cases.size()) < count) {
        float offset = offsets[property->cases.size() % 3];
        Vec3 centre = Vec3(offset) + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 10.0f;
        float radius = 0.1f + 10.0f * rng.uniform();
        Vec3 away(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
        if (!(glm::length(away) > 0.1f)) continue;
        Vec3 origin = centre + glm::normalize(away) * radius * (rng.uniform() < 0.2f ? 0.5f : 2.0f + 20.0f * rng.uniform());
        Vec3 target = centre + radius * 1.5f * Vec3(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
        Ray ray = makeRay(origin, target - origin);
        // The exact answer in double; near-tangent rays are left out.
        DVec3 d(ray.direction), f = DVec3(origin) - DVec3(centre);
        double a = glm::dot(d, d), bHalf = -glm::dot(f, d);
        DVec3 perpendicular = f + (bHalf / a) * d;
        double margin = 1.0 - glm::dot(perpendicular, perpendicular) / (double(radius) * radius);
        if (std::abs(margin) < 1e-2) continue;
        SphereCase c{"random sphere", centre, radius, ray, false, 0, 0};
        if (margin > 0) {
            double root = std::sqrt(a * double(radius) * radius * margin);
            double t0 = (bHalf - root) / a, t1 = (bHalf + root) / a;
            double t = t0 > 0 ? t0 : t1;
            if (t > 0) {
                c.hit = true;
                c.t = float(t);
                c.tolerance = float(1e-5 * (1 + glm::length(f) / std::sqrt(a) / std::max(t, 1e-3)));
            }
        }
        property->cases.push_back(c);
    }
    return property;
}

TestGroup sphereGroup(uint64_t seed) {
    auto table = std::make_shared<std::vector<SphereCase>>(sphereCases());
    auto property = sphereProperty(seed, 20000);
    auto propertyCases = std::make_shared<std::vector<SphereCase>>(property->cases);
    TestGroup group;
    group.assignment = kA0;
    group.title = "a0 sphere test";
    group.phases = {noSetUp(), sphereTablePhase(table), sphereTablePhase(propertyCases)};
    group.score = [=](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult a = makeResult(kA0, "a0/sphere/cases");
        scoreSphereTable(*table, run.phases[1], a);
        TestResult b = makeResult(kA0, "a0/sphere/property");
        scoreSphereTable(*propertyCases, run.phases[2], b);
        // A property test passes only when every case does: no partial credit for luck.
        if (b.status != TestStatus::Passed) b.fraction = 0.0;
        results.push_back(std::move(a));
        results.push_back(std::move(b));
    };
    return group;
}

}  // namespace

std::vector<TestGroup> a0Groups(GradingContext& context) {
    return {slabGroup(context.seed), triangleGroup(context.seed), sphereGroup(context.seed)};
}

}  // namespace rtlab::grader
