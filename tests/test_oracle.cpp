// The oracle against closed-form intersections.
#include "framework/oracle/oracle.h"

#include <doctest/doctest.h>

using namespace rtlab;

static Scene oneTriangleAndSphere() {
    Scene scene;
    scene.triangles.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    scene.triangles.indices = {{0, 1, 2}};
    scene.triangles.material = {0};
    scene.triangles.smooth = {0};
    scene.spheres.push_back(Sphere{{0, 0, -10}, 2.0f, 0});
    scene.materials.push_back(Material{});
    return scene;
}

TEST_CASE("oracle: triangle hit at the analytic distance, barycentrics on an edge") {
    Scene scene = oneTriangleAndSphere();
    Oracle oracle(scene);
    OracleHit hit = oracle.closestHit({{0.25, 0.25, 3.0}, {0, 0, -1}});
    REQUIRE(hit.hit);
    CHECK(hit.prim == 0);
    CHECK(hit.t == 3.0);
    CHECK(hit.edgeMargin == doctest::Approx(0.25));

    OracleHit edge = oracle.closestHit({{0.5, 0.5, 1.0}, {0, 0, -1}});  // on the hypotenuse
    REQUIRE(edge.hit);
    CHECK(edge.prim == 0);
    CHECK(edge.edgeMargin == 0.0);

    CHECK_FALSE(oracle.closestHit({{0.6, 0.6, 1.0}, {0, 0, -1}}).prim == 0);
}

TEST_CASE("oracle: sphere behind the triangle, from outside and from inside") {
    Scene scene = oneTriangleAndSphere();
    Oracle oracle(scene);
    OracleHit hit = oracle.closestHit({{-3, -3, 5}, {0, 0, -1}});
    CHECK_FALSE(hit.hit);
    OracleHit s = oracle.closestHit({{-0.5, -0.5, 5}, {0, 0, -1}});
    REQUIRE(s.hit);
    CHECK(s.prim == 1);
    CHECK(s.t == doctest::Approx(15.0 - std::sqrt(4.0 - 0.5)));
    OracleHit inside = oracle.closestHit({{0, 0, -10}, {1, 0, 0}});
    REQUIRE(inside.hit);
    CHECK(inside.t == doctest::Approx(2.0));
}

TEST_CASE("oracle: tMin < t <= tMax and NaN rays") {
    Scene scene = oneTriangleAndSphere();
    Oracle oracle(scene);
    OracleRay ray{{0.25, 0.25, 3.0}, {0, 0, -1}};
    ray.tMax = 3.0;
    CHECK(oracle.closestHit(ray).hit);  // t == tMax counts
    ray.tMin = 3.0;
    ray.tMax = 4.0;
    CHECK_FALSE(oracle.closestHit(ray).prim == 0);  // t == tMin does not
    OracleRay nan{{std::nan(""), 0.25, 3.0}, {0, 0, -1}};
    CHECK_FALSE(oracle.anyHit(nan));
}
