#include "grader/kit/stress_cases.h"

#include <cmath>
#include <limits>

namespace rtlab::grader {

Ray makeRay(const Vec3& origin, const Vec3& direction, float tMin, float tMax) {
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.tMin = tMin;
    ray.tMax = tMax;
    return ray;
}

std::vector<BoxCase> boxCases() {
    const Bounds3f unit(Vec3(0.0f), Vec3(1.0f));
    const float p = 0.0f, m = -0.0f;
    std::vector<BoxCase> cases = {
        {"BOX-01.1", unit, makeRay({0.5f, 0.5f, -1}, {p, p, 1}), true, 1},
        {"BOX-01.2", unit, makeRay({0.5f, 0.5f, -1}, {m, m, 1}), true, 1},
        {"BOX-01.3", unit, makeRay({0, 0.5f, -1}, {p, 0, 1}), true, 1},
        {"BOX-01.4", unit, makeRay({0, 0.5f, -1}, {m, 0, 1}), true, 1},
        {"BOX-01.5", unit, makeRay({1, 0.5f, -1}, {p, 0, 1}), true, 1},
        {"BOX-01.6", unit, makeRay({1, 0.5f, -1}, {m, 0, 1}), true, 1},
        {"BOX-01.7", unit, makeRay({1, 1, -1}, {0, 0, 1}), true, 1},
        {"BOX-01.8", unit, makeRay({2, 0.5f, -1}, {0, 0, 1}), false, 0},
        {"BOX-01.9", unit, makeRay({-1, 0.5f, -1}, {m, 0, 1}), false, 0},
        {"BOX-01.10", unit, makeRay({0.5f, 0.5f, 2}, {0, 0, 1}), false, 0},
        {"BOX-01.11", unit, makeRay({0.5f, 0.5f, 0.5f}, {0, 0, 1}), true, 0},
        {"BOX-01.12", unit, makeRay({2, 2, 2}, {-1, -1, -1}), true, 1},
        {"BOX-01.13", unit, makeRay({2, 0, 2}, {-1, 1, -1}), true, 1},
        // Rows 3 and 6 turned so that the face plane is z, the last axis: a NaN that an update
        // lets through survives only there (a later axis would overwrite it).
        {"BOX-01.14", unit, makeRay({-1, 0.5f, 0}, {1, 0, p}), true, 1},
        {"BOX-01.15", unit, makeRay({-1, 0.5f, 1}, {1, 0, m}), true, 1},
        {"BOX-02.1", Bounds3f({-1, -1, 5}, {1, 1, 5}), makeRay({0.25f, 0.25f, 0}, {0, 0, 1}), true, 5},
        // The query ends on the flat box: entry = exit = tMax = 5. The far-distance factor lifts
        // every other exit above its entry, so only here does a strict tEnter < tExit show.
        {"BOX-02.2 (tMax 5)", Bounds3f({-1, -1, 5}, {1, 1, 5}), makeRay({0.25f, 0.25f, 0}, {0, 0, 1}, 0, 5), true, 5},
        {"BOX-03.A", Bounds3f({0, 0, 5}, {1, 1, 5}), makeRay({-0.041f, -0.905f, 3.322f}, {0.402f, 0.905f, 1.678f}), true, 1},
        {"BOX-03.B", Bounds3f({0, -1, 5}, {1, 0, 5}), makeRay({-0.041f, -0.905f, 3.322f}, {0.402f, 0.905f, 1.678f}), true, 1},
        {"BOX-06.1 (tMax 5)", unit, makeRay({0.5f, 0.5f, -10}, {0, 0, 1}, 0, 5), false, 0},
        {"BOX-06.2 (tMax 10)", unit, makeRay({0.5f, 0.5f, -10}, {0, 0, 1}, 0, 10), true, 10},
        {"BOX-06.3 (inside)", unit, makeRay({0.5f, 0.5f, 0.5f}, {1, 0, 0}), true, 0},
        {"BOX-06.4 (behind)", unit, makeRay({0.5f, 0.5f, 2}, {0, 0, 1}), false, 0},
        {"BOX-06.5 (tMin past the exit)", unit, makeRay({0.5f, 0.5f, -10}, {0, 0, 1}, 12, kInfinity), false, 0},
        {"BOX-06.6 (tMin inside: enter = tMin)", unit, makeRay({0.5f, 0.5f, -10}, {0, 0, 1}, 10.5f, kInfinity), true, 10.5f},
    };
    return cases;
}

std::vector<TriangleCase> triangleCases() {
    using Tri = std::array<Vec3, 3>;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Tri unit{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const Vec3 a(0.1f, 0.1f, 0), b(1.3f, 0.2f, 0), c(0.2f, 1.1f, 0), d(1.4f, 1.2f, 0);
    const Vec3 centre(0.31f, 0.75f, 0);
    const Vec3 ring[6] = {{1.11f, 0.75f, 0.1f}, {0.71f, 1.45f, 0.1f}, {-0.09f, 1.35f, 0.1f},
                          {-0.49f, 0.75f, 0.1f}, {-0.09f, 0.15f, 0.1f}, {0.71f, 0.05f, 0.1f}};
    std::vector<Tri> fan;
    for (int k = 0; k < 6; ++k) fan.push_back({centre, ring[k], ring[(k + 1) % 6]});
    const float big = 1048576.0f;
    const float belowFive = std::nextafter(5.0f, 0.0f);
    const Ray down = makeRay({0.2f, 0.2f, 1}, {0, 0, -1});
    std::vector<TriangleCase> cases = {
        {"TRI-01 shared edge", {{a, b, c}, {c, b, d}}, makeRay({-1.5f, 3, 2}, {2.03f, -2.17f, -2}), true, 1, 1e-5f},
        {"TRI-02 shared vertex", fan, makeRay({2.4f, -0.9f, 1.7f}, {-2.09f, 1.65f, -1.7f}), true, 1, 1e-5f},
        {"TRI-05 mirrored half (u > 1 || v > 1 bug)", {unit}, makeRay({0.75f, 0.75f, 1}, {0, 0, -1}), false, 0, 0},
        {"TRI-06 near miss", {unit}, makeRay({0.5f, 0.50001f, 1}, {0, 0, -1}), false, 0, 0},
        {"TRI-06 near hit", {unit}, makeRay({0.5f, 0.49999f, 1}, {0, 0, -1}), true, 1, 1e-6f},
        {"TRI-07 from above", {{Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)}}, makeRay({0.25f, 0.25f, 1}, {0, 0, -1}), true, 1, 1e-6f},
        {"TRI-07 from below", {{Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)}}, makeRay({0.25f, 0.25f, -1}, {0, 0, 1}), true, 1, 1e-6f},
        {"TRI-08 tiny triangle", {{Vec3(0, 0, 0), Vec3(1e-4f, 0, 0), Vec3(0, 1e-4f, 0)}}, makeRay({2.5e-5f, 2.5e-5f, 1}, {0, 0, -1}), true, 1, 1e-6f},
        {"TRI-11 coplanar ray", {unit}, makeRay({-1, 0.25f, 0}, {1, 0, 0}), false, 0, 0},
        {"TRI-12 collinear", {{Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)}}, makeRay({1, 1, 5}, {0, 0, -1}), false, 0, 0},
        {"TRI-12 point", {{Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)}}, makeRay({1, 1, 5}, {0, 0, -1}), false, 0, 0},
        {"TRI-12 duplicate vertex", {{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)}}, makeRay({0.5f, 0, 5}, {0, 0, -1}), false, 0, 0},
        {"TRI-12 valid V behind", {{Vec3(0, 0, -1), Vec3(4, 0, -1), Vec3(0, 4, -1)}}, makeRay({1, 1, 5}, {0, 0, -1}), true, 6, 1e-6f},
        {"TRI-13 NaN vertex", {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(nan, 1, 0)}}, down, false, 0, 0},
        {"TRI-13 inf vertex", {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(kInfinity, 1, 0)}}, down, false, 0, 0},
        {"TRI-13 valid prim 1", {{Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0, 1, -1)}}, down, true, 2, 1e-6f},
        {"TRI-13 prim 1 with tMax 1.5", {{Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0, 1, -1)}}, makeRay({0.2f, 0.2f, 1}, {0, 0, -1}, 0, 1.5f), false, 0, 0},
        {"TRI-14 zero direction", {unit}, makeRay({0.2f, 0.2f, 1}, {0, 0, 0}), false, 0, 0},
        {"TRI-14 NaN origin", {unit}, makeRay({nan, 0.2f, 1}, {0, 0, -1}), false, 0, 0},
        {"TRI-14 infinite direction", {unit}, makeRay({0.2f, 0.2f, 1}, {kInfinity, 0, -1}), false, 0, 0},
        {"TRI-15 tMax = 5", {unit}, makeRay({0.25f, 0.25f, 5}, {0, 0, -1}, 0, 5), true, 5, 1e-6f},
        {"TRI-15 tMax = next below 5", {unit}, makeRay({0.25f, 0.25f, 5}, {0, 0, -1}, 0, belowFive), false, 0, 0},
        {"TRI-15 tMin = 5", {unit}, makeRay({0.25f, 0.25f, 5}, {0, 0, -1}, 5, kInfinity), false, 0, 0},
        {"TRI-15 tMin = next below 5", {unit}, makeRay({0.25f, 0.25f, 5}, {0, 0, -1}, belowFive, kInfinity), true, 5, 1e-6f},
        {"TRI-15 origin on the triangle", {unit}, makeRay({0.25f, 0.25f, 0}, {0, 0, -1}), false, 0, 0},
        {"BIG-01 hit at 2^20", {{Vec3(big, big, big), Vec3(big + 8, big, big), Vec3(big, big + 8, big)}},
         makeRay({big + 1, big + 1, big + 100}, {0.001f, 0.002f, -1}), true, 100, 1e-6f},
    };
    return cases;
}

std::vector<SphereCase> sphereCases() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Vec3 origin(0.0f);
    const float big = 1048576.0f;
    std::vector<SphereCase> cases = {
        {"from outside", origin, 1, makeRay({0, 0, 5}, {0, 0, -1}), true, 4, 1e-6f},
        {"from inside: the far root", origin, 1, makeRay({0, 0, 0}, {0, 0, 1}), true, 1, 1e-6f},
        {"sphere behind the ray", origin, 1, makeRay({0, 0, 5}, {0, 0, 1}), false, 0, 0},
        {"tMax before the sphere", origin, 1, makeRay({0, 0, 5}, {0, 0, -1}, 0, 3.5f), false, 0, 0},
        {"tMin past the near root", origin, 1, makeRay({0, 0, 5}, {0, 0, -1}, 4.5f, kInfinity), true, 6, 1e-6f},
        {"passing beside", origin, 1, makeRay({1.5f, 0, 5}, {0, 0, -1}), false, 0, 0},
        {"direction not unit length", origin, 1, makeRay({0, 0, 5}, {0, 0, -2}), true, 2, 1e-6f},
        {"distant small sphere, missed by 0.01", {0, 0, -1e4f}, 0.01f, makeRay({0.02f, 0, 0}, {0, 0, -1}), false, 0, 0},
        {"distant small sphere, hit", {0, 0, -1e4f}, 0.01f, makeRay({0.005f, 0, 0}, {0, 0, -1}), true,
         1e4f - std::sqrt(0.01f * 0.01f - 0.005f * 0.005f), 1e-5f},
        {"centre at 2^20", {big, big, big}, 2, makeRay({big, big, big + 100}, {0, 0, -1}), true, 98, 1e-6f},
        {"NaN origin", origin, 1, makeRay({nan, 0, 5}, {0, 0, -1}), false, 0, 0},
        {"zero direction", origin, 1, makeRay({0, 0, 5}, {0, 0, 0}), false, 0, 0},
    };
    return cases;
}

}  // namespace rtlab::grader
