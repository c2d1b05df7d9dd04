// The packet test of four triangles (fast/triangle_packet.h) against a loop over a0's
// intersectTriangle, bit for bit: the same lane's id, distance and barycentrics, and the same
// any-hit answer. The rays aim at the triangles' vertices and edges, where a float estimate of
// an edge function can have the wrong sign, so the test's float screen must leave those lanes
// to the exact arithmetic.
//
// Mutants it catches: a screen whose products the compiler may fuse into the subtraction
// (caught by test_triangle_packet_fma, built with FMA contraction, on the vertex and grazing
// rays), one without its floor (tiny triangles, whose products underflow), and a shear axis
// chosen otherwise than a0 chooses it where components tie (> for >=).
#include "fast/triangle_packet.h"
#include "framework/core/float_bits.h"
#include "framework/core/pcg32.h"
#include "framework/interface/a0_intersect.h"

#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

using Triangle = std::array<Vec3, 3>;

// What a loop over the used lanes in order reports: the nearest hit, the last of equally near.
struct LoopHit {
    int lane = -1;
    TriangleHit hit{};
};

LoopHit loopOver(const Ray& ray, std::span<const Triangle> triangles) {
    LoopHit best;
    float tMax = ray.tMax;
    for (int lane = 0; lane < int(triangles.size()); ++lane) {
        TriangleHit hit;
        const Triangle& t = triangles[lane];
        if (intersectTriangle(ray, tMax, t[0], t[1], t[2], &hit)) {
            best = {lane, hit};
            tMax = hit.t;
        }
    }
    return best;
}

TrianglePacket packetOf(std::span<const Triangle> triangles) {
    TrianglePacket packet;
    for (int lane = 0; lane < int(triangles.size()); ++lane) packet.set(lane, uint32_t(100 + lane), triangles[lane]);
    packet.pad(int(triangles.size()), true);
    return packet;
}

// Compares the packet with the loop on one ray; returns a description of the first difference.
std::string difference(const Ray& ray, std::span<const Triangle> triangles) {
    const TrianglePacket packet = packetOf(triangles);
    const ShearedRay sheared(ray);
    const LoopHit expected = loopOver(ray, triangles);
    const PacketHit got = sheared.closest(packet, ray.tMax);
    if (sheared.anyHit(packet, ray.tMax) != (expected.lane >= 0)) return "any-hit differs from the loop";
    if ((got.lane >= 0) != (expected.lane >= 0)) return got.lane >= 0 ? "a hit the loop misses" : "a hit missed";
    if (got.lane < 0) return "";
    if (packet.prim[got.lane] != uint32_t(100 + expected.lane)) return "another triangle's hit";
    if (std::bit_cast<uint32_t>(got.hit.t) != std::bit_cast<uint32_t>(expected.hit.t) ||
        std::bit_cast<uint32_t>(got.hit.b1) != std::bit_cast<uint32_t>(expected.hit.b1) ||
        std::bit_cast<uint32_t>(got.hit.b2) != std::bit_cast<uint32_t>(expected.hit.b2))
        return "the same triangle, other bits";
    return "";
}

// A fan of four triangles around a centre, sharing edges, at a given scale and offset.
// Draws x, y, z in that order (the order of a constructor's arguments is unspecified).
Vec3 uniform3(Pcg32& random) {
    const float x = random.uniform(), y = random.uniform(), z = random.uniform();
    return Vec3(x, y, z);
}

std::array<Triangle, 4> fan(Pcg32& random, float scale, const Vec3& offset) {
    auto point = [&] { return offset + scale * (uniform3(random) - 0.5f); };
    const Vec3 centre = point();
    std::array<Vec3, 5> rim{point(), point(), point(), point(), point()};
    std::array<Triangle, 4> triangles;
    for (int i = 0; i < 4; ++i) triangles[i] = {centre, rim[i], rim[i + 1]};
    return triangles;
}

// A target on the fan: a vertex, a point of an edge (rounded to float, so a hair off it), or
// a point inside or just beside a triangle.
Vec3 target(Pcg32& random, const std::array<Triangle, 4>& triangles) {
    const Triangle& t = triangles[random.next() % 4];
    const int a = int(random.next() % 3), b = (a + 1) % 3;
    const float s = random.uniform();
    switch (random.next() % 3) {
        case 0: return t[a];
        case 1: return t[a] + s * (t[b] - t[a]);
        default: {
            const float u = random.uniform() * 1.2f - 0.1f, v = (1.0f - u) * random.uniform();
            return t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
        }
    }
}

void checkScale(float scale, const Vec3& offset, uint64_t seed, float minimumHitShare = 0.4f) {
    Pcg32 random(seed, 7);
    int rays = 0, hits = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const std::array<Triangle, 4> triangles = fan(random, scale, offset);
        const Vec3 aim = target(random, triangles);
        const Vec3 from = aim + 3.0f * scale * (uniform3(random) - Vec3(0.5f, 0.5f, -0.1f));
        const Ray ray{from, aim - from};
        // Every number of used lanes, so that the padding is tested too.
        for (size_t used = 1; used <= triangles.size(); ++used) {
            const std::span<const Triangle> lanes(triangles.data(), used);
            const std::string why = difference(ray, lanes);
            INFO("scale ", scale, ", trial ", trial, ", ", used, " lanes");
            REQUIRE_MESSAGE(why.empty(), why);
            ++rays;
            hits += loopOver(ray, lanes).lane >= 0;
        }
    }
    // The rays are meant to hit often: most aim at a triangle of the fan. Fewer hit below 1e-19,
    // where 1 / det overflows for the smallest triangles and a0 reports no hit, and with FMA
    // contraction, where the shear is computed unrounded and a ray aimed at a vertex passes an
    // ulp beside it (beside the fan for its outer vertices).
    CHECK(hits > rays * minimumHitShare);
}

}  // namespace

TEST_CASE("the packet test reports the loop's hit, bit for bit, on rays through vertices and edges") {
    checkScale(1.0f, Vec3(0.0f), 1);
    checkScale(1e4f, Vec3(3e5f, -2e5f, 1e5f), 2);  // far from the origin: large products
    checkScale(1e-3f, Vec3(0.5f, 0.25f, -0.75f), 3);
}

TEST_CASE("the packet test agrees with the loop on rays that graze an edge next to a vertex") {
    // A ray down the z axis and an edge from b to c that passes within an ulp of it, c nearly
    // opposite b and far longer: the edge function's products are large and nearly equal, and
    // their difference in float often has the wrong sign (about one ray in five here). Each
    // packet holds the triangles on both sides of the edge, so one of them is hit.
    Pcg32 random(6, 7);
    const Ray ray{Vec3(0.0f, 0.0f, 10.0f), Vec3(0.0f, 0.0f, -1.0f)};
    int hits = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const float bx = random.uniform() - 0.5f, by = random.uniform() - 0.5f, k = 1.0f + 1000.0f * random.uniform();
        const float cx = std::nextafter(-k * bx, random.next() & 1 ? 1.0f : -1.0f), cy = -k * by;
        const float bz = random.uniform(), cz = random.uniform();
        const Vec3 b(bx, by, bz), c(cx, cy, cz);
        const Vec3 side = Vec3(-by, bx, 0.0f) * (1.0f + random.uniform());
        const std::array<Triangle, 2> triangles{Triangle{side, b, c}, Triangle{-side, c, b}};
        const std::string why = difference(ray, triangles);
        INFO("trial ", trial);
        REQUIRE_MESSAGE(why.empty(), why);
        hits += loopOver(ray, triangles).lane >= 0;
    }
    CHECK(hits == 20000);  // watertight: the shared edge lets no ray through
}

TEST_CASE("the packet test agrees with the loop on triangles so small that float products underflow") {
    checkScale(8e-20f, Vec3(0.0f), 4, 0.05f);
    checkScale(1.1e-19f, Vec3(0.0f), 5, 0.2f);
}

TEST_CASE("the packet test shears along a0's axis where the direction's largest components tie") {
    // The axis that becomes z is the largest |component|, the first of equals, as a0's
    // maxComponentIndex picks it; another axis gives other bits of t and the barycentrics.
    const std::array<Vec3, 7> directions{Vec3(1, 1, 0.5f), Vec3(-1, 0.5f, 1), Vec3(0.25f, -1, 1), Vec3(1, 1, 1),
                                         Vec3(-1, -1, -1), Vec3(0.75f, 1, -1), Vec3(1, -0.5f, -1)};
    Pcg32 random(8, 7);
    for (int trial = 0; trial < 4000; ++trial) {
        const std::array<Triangle, 4> triangles = fan(random, 1.0f, Vec3(0.0f));
        const Vec3 aim = target(random, triangles);
        const Vec3& direction = directions[trial % directions.size()];
        const Ray ray{aim - 3.0f * direction, direction};
        const std::string why = difference(ray, triangles);
        INFO("trial ", trial, ", direction ", direction.x, " ", direction.y, " ", direction.z);
        REQUIRE_MESSAGE(why.empty(), why);
    }
}

TEST_CASE("padding repeats the last triangle, and a lane of no triangle is never hit") {
    const Triangle triangle{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)};
    TrianglePacket packet;
    packet.set(0, 42, triangle);
    packet.pad(1, true);
    for (int lane = 1; lane < TrianglePacket::kLanes; ++lane) CHECK(packet.prim[lane] == 42u);
    const Ray ray{Vec3(0, 0, 5), Vec3(0, 0, -1)};
    const PacketHit hit = ShearedRay(ray).closest(packet, kInfinity);
    REQUIRE(hit.lane >= 0);
    CHECK(packet.prim[hit.lane] == 42u);
    CHECK(hit.hit.t == 5.0f);

    packet.pad(1, false);  // the last lane holds a sphere: no copies
    for (int lane = 1; lane < TrianglePacket::kLanes; ++lane) CHECK(packet.prim[lane] == kNoPrimitive);
    packet.pad(0, false);
    CHECK_FALSE(ShearedRay(ray).anyHit(packet, kInfinity));
}

TEST_CASE("a ray of zero direction hits nothing, as in a0, with the origin inside every triangle") {
    // The packet test has no branch for it (ShearedRay): the shear's 0 / 0 makes every t NaN.
    const std::array<Triangle, 4> triangles{Triangle{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)},
                                            Triangle{Vec3(-1, -1, 0), Vec3(0, 1, 0), Vec3(1, -1, 0)},
                                            Triangle{Vec3(0, -1, -1), Vec3(0, -1, 1), Vec3(0, 1, 0)},
                                            Triangle{Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(0, 0, 1)}};
    for (const Vec3 zero : {Vec3(0.0f), Vec3(-0.0f), Vec3(0.0f, -0.0f, 0.0f)}) {
        const Ray ray{Vec3(0.0f), zero, -kInfinity, kInfinity};
        CHECK(difference(ray, triangles).empty());
        CHECK(loopOver(ray, triangles).lane < 0);
    }
}
