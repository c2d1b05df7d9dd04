// The stress catalogue (docs/conventions.md#stress-catalogue) as far as it applies to a0, run
// against the reference solution: the slab test (BOX-*), the watertight triangle (TRI-*,
// BIG-01) and the sphere. tests/CMakeLists.txt builds this file twice: as test_a0_stress, and
// as test_a0_stress_fma with the a0 solution compiled with FMA contraction (ENV-01).
#include "framework/core/float_bits.h"
#include "framework/core/pcg32.h"
#include "framework/interface/a0_intersect.h"
#include "framework/scene/icosphere_mesh.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

using namespace rtlab;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Triangle {
    Vec3 p0, p1, p2;
};

// The catalogue's triangle query: closest-hit style, with the given tMax.
std::optional<TriangleHit> hitTriangle(const Ray& ray, const Triangle& tri, float tMax = kInfinity) {
    TriangleHit hit;
    if (!intersectTriangle(ray, tMax, tri.p0, tri.p1, tri.p2, &hit)) return std::nullopt;
    return hit;
}

std::optional<float> hitBox(const Bounds3f& box, const Ray& ray, float tMin = 0.0f, float tMax = kInfinity) {
    float tEnter;
    if (!intersectBox(box, RayInverse(ray), tMin, tMax, &tEnter)) return std::nullopt;
    return tEnter;
}

std::optional<float> hitSphere(const Ray& ray, const Vec3& centre, float radius, float tMax = kInfinity) {
    float t;
    if (!intersectSphere(ray, tMax, centre, radius, &t)) return std::nullopt;
    return t;
}

// "Exactly computed" cases: within max(1e-6, 4 ulp) relative.
bool exactT(float t, float expected) {
    float ulps4 = 4.0f * (nextFloatUp(std::abs(expected)) - std::abs(expected));
    return std::abs(t - expected) <= std::max(1e-6f * std::abs(expected), ulps4);
}
// "Approximate" cases (marked with the catalogue's ~): 1e-5 relative in float.
bool approxT(float t, float expected) { return std::abs(t - expected) <= 1e-5f * std::abs(expected); }

const Triangle kUnitTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

}  // namespace

// --- A. Triangle intersection ------------------------------------------------------------------

TEST_CASE("TRI-01: the regression ray through the shared diagonal of a quad hits") {
    Vec3 A(0.1f, 0.1f, 0), B(1.3f, 0.2f, 0), C(0.2f, 1.1f, 0), D(1.4f, 1.2f, 0);
    Ray ray{{-1.5f, 3.0f, 2.0f}, {2.03f, -2.17f, -2.0f}};
    auto h0 = hitTriangle(ray, {A, B, C});
    auto h1 = hitTriangle(ray, {C, B, D});
    REQUIRE((h0 || h1));
    CHECK(approxT(h0 ? h0->t : h1->t, 1.0f));
}

TEST_CASE("TRI-02: the regression ray through the centre of a six-triangle fan hits") {
    Vec3 c(0.31f, 0.75f, 0);
    Vec3 r[6] = {{1.11f, 0.75f, 0.1f}, {0.71f, 1.45f, 0.1f}, {-0.09f, 1.35f, 0.1f},
                 {-0.49f, 0.75f, 0.1f}, {-0.09f, 0.15f, 0.1f}, {0.71f, 0.05f, 0.1f}};
    Ray ray{{2.4f, -0.9f, 1.7f}, {-2.09f, 1.65f, -1.7f}};
    int hits = 0;
    for (int k = 0; k < 6; ++k)
        if (auto h = hitTriangle(ray, {c, r[k], r[(k + 1) % 6]})) {
            ++hits;
            CHECK(approxT(h->t, 1.0f));
        }
    CHECK(hits >= 1);
}

TEST_CASE("TRI-03: 1e5 rays at random shared edges: never both neighbours missed") {
    Pcg32 rng(2013, 1);
    auto u = [&] { return 2.0f * rng.uniform() - 1.0f; };
    auto point = [&] { return Vec3(u(), u(), u()); };
    int tested = 0, leaks = 0, farFromOne = 0;
    for (int i = 0; i < 100000; ++i) {
        Vec3 A = point(), B = point(), C = point();
        Vec3 D = B + C - A;
        if (i % 2 == 1) D += 0.3f * glm::normalize(glm::cross(B - A, C - A));  // folded variant
        float s = 0.001f + 0.998f * rng.uniform();
        Vec3 P = B + s * (C - B);
        Vec3 o(3 * u(), 3 * u(), 4 + 3 * u());
        Vec3 d = P - o;
        // Silhouettes (A and D on the same side of the plane through o, B, C) and grazing rays
        // are not part of the property.
        DVec3 n = glm::cross(DVec3(B) - DVec3(o), DVec3(C) - DVec3(o));
        if (glm::dot(n, DVec3(A) - DVec3(o)) * glm::dot(n, DVec3(D) - DVec3(o)) >= 0) continue;
        auto grazing = [&](const Vec3& p0, const Vec3& p1, const Vec3& p2) {
            DVec3 normal = glm::normalize(glm::cross(DVec3(p1) - DVec3(p0), DVec3(p2) - DVec3(p0)));
            return std::abs(glm::dot(normal, glm::normalize(DVec3(d)))) < 1e-3;
        };
        if (grazing(A, B, C) || grazing(C, B, D)) continue;
        ++tested;
        Ray ray{o, d};
        auto h0 = hitTriangle(ray, {A, B, C});
        auto h1 = hitTriangle(ray, {C, B, D});
        if (!h0 && !h1) ++leaks;
        for (const auto& h : {h0, h1})
            if (h && std::abs(h->t - 1.0f) > 1e-4f) ++farFromOne;
    }
    CAPTURE(tested);
    CHECK(tested > 30000);
    CHECK(leaks == 0);
    CHECK(farFromOne == 0);
}

TEST_CASE("TRI-04: 2e5 rays at edges and 2e5 at vertices of a closed icosphere never leak") {
    IndexedMesh mesh = icosphereMesh(2);
    REQUIRE(mesh.triangles.size() == 320);
    // Which triangles touch each edge and each vertex: the ones a ray aimed there must find.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edgeTriangles;
    std::vector<std::vector<uint32_t>> vertexTriangles(mesh.positions.size());
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            uint32_t a = mesh.triangles[t][e], b = mesh.triangles[t][(e + 1) % 3];
            edgeTriangles[std::minmax(a, b)].push_back(t);
            vertexTriangles[a].push_back(t);
        }
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& [edge, tris] : edgeTriangles) {
        REQUIRE(tris.size() == 2);  // closed
        edges.push_back(edge);
    }
    auto triangle = [&](uint32_t t) {
        const auto& i = mesh.triangles[t];
        return Triangle{mesh.positions[i[0]], mesh.positions[i[1]], mesh.positions[i[2]]};
    };
    const Vec3 origin(0.1f, -0.2f, 0.05f);
    auto hitsAny = [&](const Ray& ray, const std::vector<uint32_t>& candidates, int* badT) {
        bool any = false;
        for (uint32_t t : candidates)
            if (auto h = hitTriangle(ray, triangle(t))) {
                any = true;
                if (std::abs(h->t - 1.0f) > 1e-4f) ++*badT;
            }
        return any;
    };

    Pcg32 rng(4, 4);
    int edgeLeaks = 0, vertexLeaks = 0, badT = 0;
    for (int i = 0; i < 200000; ++i) {
        auto [a, b] = edges[rng.next() % edges.size()];
        float s = 0.001f + 0.998f * rng.uniform();
        Vec3 P = mesh.positions[a] + s * (mesh.positions[b] - mesh.positions[a]);
        if (!hitsAny(Ray{origin, P - origin}, edgeTriangles[{a, b}], &badT)) ++edgeLeaks;
    }
    for (int i = 0; i < 200000; ++i) {
        uint32_t v = rng.next() % mesh.positions.size();
        if (!hitsAny(Ray{origin, mesh.positions[v] - origin}, vertexTriangles[v], &badT)) ++vertexLeaks;
    }
    CHECK(edgeLeaks == 0);
    CHECK(vertexLeaks == 0);
    CHECK(badT == 0);
}

TEST_CASE("the mistake u > 1 || v > 1: the mirrored half of the parallelogram is a miss") {
    // TRI-05 (docs/conventions.md#stress-catalogue), the classic Moller-Trumbore student bug:
    // (0.75, 0.75) lies in the parallelogram spanned by the unit triangle, outside the triangle.
    CHECK_FALSE(hitTriangle(Ray{{0.75f, 0.75f, 1.0f}, {0.0f, 0.0f, -1.0f}}, kUnitTriangle));
    CHECK(hitTriangle(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}}, kUnitTriangle));
}

TEST_CASE("TRI-06: just outside the hypotenuse misses, just inside hits at t = 1") {
    CHECK_FALSE(hitTriangle(Ray{{0.5f, 0.50001f, 1.0f}, {0.0f, 0.0f, -1.0f}}, kUnitTriangle));
    auto inside = hitTriangle(Ray{{0.5f, 0.49999f, 1.0f}, {0.0f, 0.0f, -1.0f}}, kUnitTriangle);
    REQUIRE(inside);
    CHECK(exactT(inside->t, 1.0f));
}

TEST_CASE("TRI-07: both windings and both sides hit (no back-face culling)") {
    Triangle clockwise{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
    auto above = hitTriangle(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}}, clockwise);
    auto below = hitTriangle(Ray{{0.25f, 0.25f, -1.0f}, {0.0f, 0.0f, 1.0f}}, clockwise);
    REQUIRE(above);
    REQUIRE(below);
    CHECK(exactT(above->t, 1.0f));
    CHECK(exactT(below->t, 1.0f));
}

TEST_CASE("TRI-08: a triangle with 1e-4 legs is hit (no absolute epsilon on det)") {
    auto h = hitTriangle(Ray{{2.5e-5f, 2.5e-5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, {{0, 0, 0}, {1e-4f, 0, 0}, {0, 1e-4f, 0}});
    REQUIRE(h);
    CHECK(exactT(h->t, 1.0f));
}

TEST_CASE("TRI-11: a ray in the triangle's plane misses") {
    CHECK_FALSE(hitTriangle(Ray{{-1.0f, 0.25f, 0.0f}, {1.0f, 0.0f, 0.0f}}, kUnitTriangle));
}

TEST_CASE("TRI-12: degenerate triangles are never hit; the valid one behind is, at t = 6") {
    Triangle valid{{0, 0, -1}, {4, 0, -1}, {0, 4, -1}};
    Ray ray{{1.0f, 1.0f, 5.0f}, {0.0f, 0.0f, -1.0f}};
    CHECK_FALSE(hitTriangle(ray, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}));  // collinear, through (1,1,1)
    CHECK_FALSE(hitTriangle(ray, {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}));  // a point on the ray
    CHECK_FALSE(hitTriangle(Ray{{0.5f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}));
    auto h = hitTriangle(ray, valid);
    REQUIRE(h);
    CHECK(exactT(h->t, 6.0f));
}

TEST_CASE("TRI-13: a NaN or inf vertex is never hit; the finite triangle behind is, at t = 2") {
    Ray ray{{0.2f, 0.2f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    Triangle finite{{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    for (float bad : {kNaN, kInfinity}) {
        CAPTURE(bad);
        Triangle broken{{0, 0, 0}, {1, 0, 0}, {bad, 1, 0}};
        CHECK_FALSE(hitTriangle(ray, broken));
        CHECK_FALSE(hitTriangle(ray, broken, 1.5f));  // the occlusion query with tMax = 1.5
        auto h = hitTriangle(ray, finite);
        REQUIRE(h);
        CHECK(exactT(h->t, 2.0f));
        CHECK_FALSE(hitTriangle(ray, finite, 1.5f));
    }
}

TEST_CASE("TRI-14: invalid rays miss and never produce a NaN t") {
    CHECK_FALSE(hitTriangle(Ray{{0.2f, 0.2f, 1.0f}, {0.0f, 0.0f, 0.0f}}, kUnitTriangle));
    CHECK_FALSE(hitTriangle(Ray{{kNaN, 0.2f, 1.0f}, {0.0f, 0.0f, -1.0f}}, kUnitTriangle));
    CHECK_FALSE(hitTriangle(Ray{{0.2f, 0.2f, 1.0f}, {kInfinity, 0.0f, -1.0f}}, kUnitTriangle));
    CHECK_FALSE(hitSphere(Ray{{0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 0.0f}}, Vec3(0.0f), 1.0f));
    CHECK_FALSE(hitSphere(Ray{{kNaN, 0.0f, -5.0f}, {0.0f, 0.0f, 1.0f}}, Vec3(0.0f), 1.0f));
}

TEST_CASE("TRI-15: tMin < t <= tMax exactly at the boundary t = 5") {
    const float next = std::nextafter(5.0f, 0.0f);
    Ray ray{{0.25f, 0.25f, 5.0f}, {0.0f, 0.0f, -1.0f}};
    CHECK(hitTriangle(ray, kUnitTriangle, 5.0f));
    CHECK_FALSE(hitTriangle(ray, kUnitTriangle, next));
    Ray fromFive = ray;
    fromFive.tMin = 5.0f;
    CHECK_FALSE(hitTriangle(fromFive, kUnitTriangle));
    fromFive.tMin = next;
    CHECK(hitTriangle(fromFive, kUnitTriangle));
    CHECK_FALSE(hitTriangle(Ray{{0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, -1.0f}}, kUnitTriangle));  // origin on it
}

TEST_CASE("BIG-01: an exact hit at 2^20") {
    const float S = 1048576.0f;
    auto h = hitTriangle(Ray{{S + 1, S + 1, S + 100}, {0.001f, 0.002f, -1.0f}}, {{S, S, S}, {S + 8, S, S}, {S, S + 8, S}});
    REQUIRE(h);
    CHECK(h->t == 100.0f);
}

// --- B. Ray-box ----------------------------------------------------------------------------------

TEST_CASE("BOX-01: the face-plane truth table, +0 and -0 directions") {
    const Bounds3f unit(Vec3(0.0f), Vec3(1.0f));
    struct Case {
        Vec3 origin, direction;
        bool hit;
    };
    const float n0 = -0.0f;
    const Case cases[] = {
        {{0.5f, 0.5f, -1}, {0, 0, 1}, true},     {{0.5f, 0.5f, -1}, {n0, n0, 1}, true},
        {{0, 0.5f, -1}, {0, 0, 1}, true},        {{0, 0.5f, -1}, {n0, 0, 1}, true},
        {{1, 0.5f, -1}, {0, 0, 1}, true},        {{1, 0.5f, -1}, {n0, 0, 1}, true},
        {{1, 1, -1}, {0, 0, 1}, true},           {{2, 0.5f, -1}, {0, 0, 1}, false},
        {{-1, 0.5f, -1}, {n0, 0, 1}, false},     {{0.5f, 0.5f, 2}, {0, 0, 1}, false},
        {{0.5f, 0.5f, 0.5f}, {0, 0, 1}, true},   {{2, 2, 2}, {-1, -1, -1}, true},
        {{2, 0, 2}, {-1, 1, -1}, true},  // touches only the corner (1, 1, 1)
        {{-1, 0.5f, 0}, {1, 0, 0}, true},  // rows 3 and 6 with the face plane z, the last axis
        {{-1, 0.5f, 1}, {1, 0, n0}, true},
    };
    int number = 1;
    for (const Case& c : cases) {
        CAPTURE(number++);
        CHECK(hitBox(unit, Ray{c.origin, c.direction}).has_value() == c.hit);
    }
}

TEST_CASE("BOX-02: a flat box is hit, entered at t = 5, also by a query that ends there") {
    const Bounds3f flat(Vec3(-1, -1, 5), Vec3(1, 1, 5));
    auto t = hitBox(flat, Ray{{0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}});
    REQUIRE(t);
    CHECK(*t <= 5.0f);
    CHECK(*t >= nextFloatDown(5.0f));
    // BOX-02.2: tMax = 5 leaves the interval [5, 5]; a strict final compare would lose it.
    CHECK(hitBox(flat, Ray{{0.25f, 0.25f, 0.0f}, {0.0f, 0.0f, 1.0f}}, 0.0f, 5.0f));
}

TEST_CASE("BOX-03: both flat boxes meeting at an edge are hit (Ize's factor)") {
    Ray ray{{-0.041f, -0.905f, 3.322f}, {0.402f, 0.905f, 1.678f}};
    CHECK(hitBox(Bounds3f(Vec3(0, 0, 5), Vec3(1, 1, 5)), ray));
    CHECK(hitBox(Bounds3f(Vec3(0, -1, 5), Vec3(1, 0, 5)), ray));
}

TEST_CASE("BOX-05: 1e6 rays through the shared edge of two flat boxes hit both") {
    // The boxes of BOX-03: their common edge is y = 0, z = 5, x in [0, 1]. (The catalogue's
    // BOX-04, whose two triangles BOX-05 refers to, is not listed; these are their leaf boxes.)
    const Bounds3f a(Vec3(0, 0, 5), Vec3(1, 1, 5)), b(Vec3(0, -1, 5), Vec3(1, 0, 5));
    Pcg32 rng(5, 5);
    int misses = 0;
    for (int i = 0; i < 1000000; ++i) {
        float xh = 0.05f + 0.9f * rng.uniform();
        float u = 2.0f * rng.uniform() - 1.0f;
        Vec3 d(u, u, 1.0f + 0.05f + 0.9f * rng.uniform());
        Ray ray{Vec3(xh, 0.0f, 5.0f) - d, d};
        if (!hitBox(a, ray) || !hitBox(b, ray)) ++misses;
    }
    CHECK(misses == 0);
}

TEST_CASE("BOX-06: the interval: tMax, an origin inside, a box behind") {
    const Bounds3f unit(Vec3(0.0f), Vec3(1.0f));
    Ray below{{0.5f, 0.5f, -10.0f}, {0.0f, 0.0f, 1.0f}};
    CHECK_FALSE(hitBox(unit, below, 0.0f, 5.0f));
    CHECK(hitBox(unit, below, 0.0f, 10.0f));
    auto inside = hitBox(unit, Ray{{0.5f, 0.5f, 0.5f}, {1.0f, 0.0f, 0.0f}});
    REQUIRE(inside);
    CHECK(*inside == 0.0f);  // clamped to tMin
    CHECK_FALSE(hitBox(unit, Ray{{0.5f, 0.5f, 2.0f}, {0.0f, 0.0f, 1.0f}}));
}

// --- Spheres (not in the catalogue; the failure modes of a0-intersect.md#spheres) --------------

TEST_CASE("sphere: a distant sphere keeps its digits (no b^2 - 4ac cancellation)") {
    // Naively, b^2 = 4e8 and 4ac = 4(1e8 - 1) round to the same float: t = 1e4 instead of 9999.
    auto t = hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 0, 1e4f), 1.0f);
    REQUIRE(t);
    CHECK(approxT(*t, 9999.0f));
    // A small sphere far away, hit off-centre: t = 1000 - sqrt(0.01^2 - 0.005^2).
    auto small = hitSphere(Ray{{0.005f, 0, 0}, {0, 0, 1}}, Vec3(0, 0, 1000), 0.01f);
    REQUIRE(small);
    CHECK(approxT(*small, 1000.0f - std::sqrt(0.0001f - 0.000025f)));
}

TEST_CASE("sphere: from inside, behind, tangent, tMax and an origin on the surface") {
    auto inside = hitSphere(Ray{{3, 4, 5}, {1, 0, 0}}, Vec3(3, 4, 5), 2.0f);
    REQUIRE(inside);
    CHECK(exactT(*inside, 2.0f));
    CHECK_FALSE(hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 0, -5), 1.0f));
    auto tangent = hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 1, 5), 1.0f);  // touches (0, 0, 5)
    REQUIRE(tangent);
    CHECK(exactT(*tangent, 5.0f));
    CHECK_FALSE(hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 0, 5), 1.0f, 3.9f));
    auto atTMax = hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 0, 5), 1.0f, 4.0f);
    REQUIRE(atTMax);
    CHECK(*atTMax == 4.0f);
    auto onSurface = hitSphere(Ray{{0, 0, 4}, {0, 0, 1}}, Vec3(0, 0, 5), 1.0f);  // t = 0 is not > tMin
    REQUIRE(onSurface);
    CHECK(exactT(*onSurface, 2.0f));
    CHECK_FALSE(hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 0, kNaN), 1.0f));
    CHECK_FALSE(hitSphere(Ray{{0, 0, 0}, {0, 0, 1}}, Vec3(0, 0, 5), kNaN));
}

#ifdef RTLAB_FMA_BUILD
// --- I. Environment ------------------------------------------------------------------------------

TEST_CASE("ENV-01: this build really contracts a*b - c*d into a fused multiply-add") {
    // a*b = 1 + 2^-11 + 2^-24 rounds to 1 + 2^-11 = c*d, so the unfused difference is 0 and
    // the fused one keeps 2^-24.
    volatile float a = 1.0f + 0x1p-12f, c = 1.0f + 0x1p-11f, d = 1.0f;
    float x = a, z = c, w = d;
    float difference = x * x - z * w;
    CHECK(difference == 0x1p-24f);
}
#endif
