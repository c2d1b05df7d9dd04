// The wide BVH's slab test on integers (fast/wide_bvh_traversal.h, intersectChildrenAsIntegers)
// against the same test in float, node by node: for every ray distancesOrderAsIntegers accepts,
// the same hit mask and the same entry distances to the bit, or a node marked undecided, which
// the walk then leaves to the float test. Built apart with SSE4.1 (tests/CMakeLists.txt), the
// least the integer test needs; a portable build's own copy of the walk has only the float test.
//
// Mutants it catches: no undecided mark (a far distance of -0, the origin on the plane the ray
// leaves a box by, then misses a box the float test hits), an integer comparison of NaN far
// distances (a ray with a zero or tiny direction component accepted), and a negative or -0
// tMin accepted.
#include "fast/wide_bvh_traversal.h"
#include "framework/core/pcg32.h"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

using namespace rtlab;

namespace {

static_assert(kIntegerSlabs, "this test is built with SSE4.1 (tests/CMakeLists.txt)");

constexpr int W = 8;

struct Outcome {
    unsigned hits = 0;
    bool undecided = false;
};

// The integer test's outcome, checked against the float test's: a decided node must agree.
Outcome compare(const WideBvhNode<W>& node, const Ray& ray, float tMax) {
    const WideRay<W> wideRay(ray);
    const ChildHits<W> asFloats = intersectChildrenAsFloats<W>(node, wideRay, tMax);
    const ChildHits<W> asIntegers = intersectChildrenAsIntegers<W>(node, wideRay, tMax);
    Outcome outcome{laneBits<W>(asIntegers.hit), asIntegers.undecided};
    if (outcome.undecided) return outcome;
    const unsigned floatHits = laneBits<W>(asFloats.hit);
    CHECK(outcome.hits == floatHits);
    for (int slot = 0; slot < W; ++slot)
        if (floatHits & (1u << slot))
            CHECK(std::bit_cast<uint32_t>(asIntegers.tEnter[slot]) == std::bit_cast<uint32_t>(asFloats.tEnter[slot]));
    return outcome;
}

// A node whose eight boxes have planes through the ray's origin (on either side, on near and far
// planes), flat boxes, boxes behind the origin, random boxes and an unused slot.
WideBvhNode<W> nodeAround(const Vec3& origin, Pcg32& rng) {
    WideBvhNode<W> node;
    auto near = [&](float value) {
        switch (rng.next() % 4) {
        case 0: return value;  // a plane through the origin
        case 1: return value - 1.0f - 4.0f * rng.uniform();
        case 2: return value + 1.0f + 4.0f * rng.uniform();
        default: return -0.0f;
        }
    };
    for (int slot = 0; slot < W - 1; ++slot) {
        Bounds3f box;
        for (int axis = 0; axis < 3; ++axis) {
            float a = near(origin[axis]), b = rng.next() % 5 == 0 ? a : near(origin[axis]);  // flat at times
            box.lower[axis] = std::min(a, b);
            box.upper[axis] = std::max(a, b);
        }
        node.setChild(slot, box, slot, 1);
    }
    node.setEmpty(W - 1);
    return node;
}

Vec3 randomDirection(Pcg32& rng) {
    Vec3 d;
    do d = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0f - Vec3(1.0f);
    while (std::fabs(d.x) < 1e-3f || std::fabs(d.y) < 1e-3f || std::fabs(d.z) < 1e-3f);
    return d;
}

}  // namespace

TEST_CASE("the integer slab test agrees with the float one, or leaves the node undecided") {
    Pcg32 rng(26, 7);
    int undecided = 0, decidedHits = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray;
        ray.origin = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 8.0f - Vec3(4.0f);
        if (i % 3 == 0) ray.origin.x = 0.0f;
        ray.direction = randomDirection(rng);
        if (i % 4 == 1) ray.tMin = rng.uniform();
        if (i % 4 == 2) ray.tMax = 0.5f + 4.0f * rng.uniform();
        if (i % 16 == 3) ray.tMax = 0.0f;
        REQUIRE(distancesOrderAsIntegers(ray));
        const WideBvhNode<W> node = nodeAround(ray.origin, rng);
        Outcome outcome = compare(node, ray, ray.tMax);
        undecided += outcome.undecided;
        decidedHits += outcome.undecided ? 0 : std::popcount(outcome.hits);
    }
    // The random boxes cover both cases often; neither count may be zero, or the test says little.
    CHECK(undecided > 100);
    CHECK(decidedHits > 1000);
}

TEST_CASE("a ray that starts on the plane it leaves a box by: a node only the float test decides") {
    // The box [0, 1]^3 and a ray from (1, 0.5, 0.5) going +x: the far distance on x is +0 * (1/d)
    // = +0, and the box is touched at t = 0. Going -x from (0, 0.5, 0.5) gives -0, which as an
    // integer is below every other distance.
    WideBvhNode<W> node;
    for (int slot = 0; slot < W; ++slot) node.setEmpty(slot);
    node.setChild(0, Bounds3f(Vec3(0.0f), Vec3(1.0f)), 0, 1);
    Ray leaving;
    leaving.origin = Vec3(0.0f, 0.5f, 0.5f);
    leaving.direction = Vec3(-1.0f, 0.25f, 0.25f);
    REQUIRE(distancesOrderAsIntegers(leaving));
    const WideRay<W> wideRay(leaving);
    CHECK(laneBits<W>(intersectChildrenAsFloats<W>(node, wideRay, kInfinity).hit) == 1u);
    const ChildHits<W> asIntegers = intersectChildrenAsIntegers<W>(node, wideRay, kInfinity);
    CHECK(asIntegers.undecided);

    Ray through = leaving;
    through.direction.x = 1.0f;  // enters at t = 0 and leaves at t = 1: decided, and hit
    Outcome outcome = compare(node, through, kInfinity);
    CHECK_FALSE(outcome.undecided);
    CHECK(outcome.hits == 1u);
}

TEST_CASE("rays the integer test must not take: a NaN far distance or a start below +0") {
    const float tiny = std::numeric_limits<float>::denorm_min();
    Ray ray;
    ray.origin = Vec3(1.0f, 0.5f, 0.5f);
    ray.direction = Vec3(1.0f, 0.5f, 0.25f);
    CHECK(distancesOrderAsIntegers(ray));
    for (float component : {0.0f, -0.0f, tiny, 0x1p-127f, kInfinity, std::numeric_limits<float>::quiet_NaN()}) {
        CAPTURE(component);
        Ray axis = ray;
        axis.direction.y = component;  // 1 / d is infinite (or 0 * inf is at hand): 0 * inf may be NaN
        CHECK_FALSE(distancesOrderAsIntegers(axis));
    }
    for (float origin : {kInfinity, -kInfinity, std::numeric_limits<float>::quiet_NaN()}) {
        Ray far = ray;
        far.origin.z = origin;
        CHECK_FALSE(distancesOrderAsIntegers(far));
    }
    for (float tMin : {-0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()}) {
        Ray early = ray;
        early.tMin = tMin;
        CHECK_FALSE(distancesOrderAsIntegers(early));
    }
    Ray reversed = ray;
    reversed.tMin = 2.0f;
    reversed.tMax = 1.0f;
    CHECK_FALSE(distancesOrderAsIntegers(reversed));
    reversed.tMax = -0.0f;
    reversed.tMin = 0.0f;
    CHECK_FALSE(distancesOrderAsIntegers(reversed));
}
