// The wide BVHs (fast/wide_bvh*.h, four and eight wide): the collapse keeps the
// binary tree's leaves and primitives, and the SIMD traversal reports exactly the hits of the
// binary traversal of the same tree. Correctness against the oracle is in test_bvh.cpp (allAccelerators).
#include "fast/wide_bvh.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/bvh_accelerator.h"
#include "framework/scene/benchmark_rays.h"
#include "tests/built_accelerator.h"
#include "tests/fetched_models.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

using namespace rtlab;

namespace {

std::unique_ptr<Accelerator> built(const std::string& name, const PrimitiveSet& prims, int maxLeaf = 4) {
    AcceleratorSpec spec{name};
    setMaxLeaf(spec, maxLeaf);
    return builtAccelerator(spec, prims);
}

}  // namespace

TEST_CASE_TEMPLATE("collapsing keeps every leaf of the binary tree and fills every node it can", Width,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>) {
    constexpr int W = Width::value;
    Scene scene = loadFetchedModel("bunny.gltf");
    PrimitiveSet prims(scene);
    auto binary = built("bvh-buckets:12", prims);
    const Bvh& bvh = dynamic_cast<const BvhAccelerator&>(*binary).bvh();
    WideBvh<W> wide = collapseToWide<W>(bvh);

    CHECK(std::equal(wide.primIndices.begin(), wide.primIndices.end(), bvh.primIndices.begin(), bvh.primIndices.end()));
    size_t binaryLeaves = 0, wideLeaves = 0, openable = 0;
    for (const BvhNode& node : bvh.nodes) binaryLeaves += node.isLeaf();
    for (const WideBvhNode<W>& node : wide.nodes) {
        int used = 0, interior = 0;
        for (int slot = 0; slot < W; ++slot) {
            bool isLeaf = node.child[slot] & kLeafFlag;
            used += !isLeaf || node.primCount[slot] > 0;
            interior += !isLeaf;
            wideLeaves += isLeaf && node.primCount[slot] > 0;
            if (!isLeaf) CHECK(node.child[slot] < wide.nodes.size());
        }
        CHECK(used >= 2);
        // A node with a free slot had no interior child left to open.
        openable += used < W && interior > 0;
    }
    CHECK(wideLeaves == binaryLeaves);
    CHECK(openable == 0);
    // n - 1 binary interior nodes become at most (n - 1) / (W - 1) + ... wide ones: each wide
    // node folds at least two binary ones whenever it has an interior child.
    CHECK(wide.nodes.size() * 2 < bvh.nodes.size() - binaryLeaves);
}

TEST_CASE_TEMPLATE("a one-leaf tree gives a root with one leaf child", Width, std::integral_constant<int, 4>,
                   std::integral_constant<int, 8>) {
    constexpr int W = Width::value;
    Bvh bvh;
    bvh.nodes.push_back(BvhNode{Bounds3f(Vec3(0.0f), Vec3(1.0f)), 0, 1, 0, 0});
    bvh.primIndices = {0};
    WideBvh<W> wide = collapseToWide<W>(bvh);
    REQUIRE(wide.nodes.size() == 1);
    CHECK(wide.nodes[0].child[0] == kLeafFlag);
    CHECK(wide.nodes[0].primCount[0] == 1);
    CHECK(wide.nodes[0].planes[WideBvhNode<W>::upperRow(2)][0] == 1.0f);
    for (int slot = 1; slot < W; ++slot) CHECK(wide.nodes[0].primCount[slot] == 0);
    CHECK(collapseToWide<W>(Bvh{}).nodes.empty());
}

TEST_CASE("the wide traversal finds exactly the binary traversal's hits, with fewer node visits") {
    for (const char* file : {"bunny.gltf", "engine.glb"}) {
        CAPTURE(file);
        Scene scene = loadFetchedModel(file);
        PrimitiveSet prims(scene);
        // Leaves of up to 8 primitives fill two triangle packets.
        for (auto [method, maxLeaf] : {std::pair{"4-sah", 4}, {"4-buckets:12", 4}, {"4-median", 8}, {"8-sah", 4},
                                       {"8-buckets:12", 4}, {"8-median", 8}}) {
            CAPTURE(method);
            CAPTURE(maxLeaf);
            auto binary = built(std::string("bvh-") + (method + 2), prims, maxLeaf);
            auto wide = built(std::string("bvh") + method, prims, maxLeaf);
            for (RayKind kind : {RayKind::Primary, RayKind::Incoherent}) {
                std::vector<Ray> rays = makeBenchmarkRays(kind, scene.bounds());
                TraversalStats binaryStats, wideStats;
                int different = 0, shadowDifferent = 0;
                for (size_t i = 0; i < rays.size(); i += 97) {
                    Ray ray = rays[i];
                    Hit a = binary->intersect(ray, binaryStats), b = wide->intersect(ray, wideStats);
                    // Same tree, same float arithmetic: the same bits.
                    different += a.prim != b.prim || a.t != b.t || a.b1 != b.b1 || a.b2 != b.b2;
                    ray.tMax = a.found() ? a.t * 0.999f : 1e3f;
                    shadowDifferent += binary->occluded(ray, binaryStats) != wide->occluded(ray, wideStats);
                }
                CHECK(different == 0);
                CHECK(shadowDifferent == 0);
                CHECK(wideStats.primitiveTests <= binaryStats.primitiveTests * 11 / 10);
                CHECK(wideStats.nodeVisits * 2 < binaryStats.nodeVisits);
            }
        }
    }
}

TEST_CASE("of equally near triangles, the wide traversal keeps the one the binary traversal keeps") {
    // Six copies of one triangle: one leaf (maxLeaf 8) over two triangle packets. A ray that
    // hits one copy hits all six at the same t; a loop over the leaf keeps the last.
    Scene scene;
    scene.materials.push_back(Material{});
    scene.triangles.positions = {Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    for (int copy = 0; copy < 6; ++copy) {
        scene.triangles.indices.push_back({0, 1, 2});
        scene.triangles.material.push_back(0);
        scene.triangles.smooth.push_back(0);
    }
    PrimitiveSet prims(scene);
    auto binary = built("bvh-median", prims, 8);
    for (std::string name : {"bvh4-median", "bvh8-median"}) {
        CAPTURE(name);
        auto wide = built(name, prims, 8);
        TraversalStats stats;
        for (int i = -8; i <= 8; ++i) {
            float x = 0.05f * i;
            Ray ray{Vec3(x, -0.2f, 1.0f), Vec3(0.01f * x, 0.02f, -1.0f)};
            Hit a = binary->intersect(ray, stats), b = wide->intersect(ray, stats);
            REQUIRE(a.found());
            CHECK(a.prim == b.prim);
            CHECK(a.t == b.t);
        }
    }
}

TEST_CASE("the wide traversal survives rays with NaN or infinite parts, and hits nothing") {
    Scene scene = loadFetchedModel("bunny.gltf");
    PrimitiveSet prims(scene);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInfinity;
    const Ray rays[] = {Ray{Vec3(nan, 1.0f, 20.0f), Vec3(0.0f, 0.0f, -1.0f)},
                        Ray{Vec3(0.0f, 1.0f, 20.0f), Vec3(0.0f, nan, -1.0f)},
                        Ray{Vec3(inf, 1.0f, 20.0f), Vec3(-1.0f, 0.0f, 0.0f)}, Ray{Vec3(0.0f, 1.0f, 20.0f), Vec3(0.0f)}};
    for (const char* name : {"bvh4-buckets:12", "bvh8-buckets:12"}) {
        CAPTURE(name);
        auto wide = built(name, prims);
        TraversalStats stats;
        for (const Ray& ray : rays) {
            CHECK_FALSE(wide->intersect(ray, stats).found());
            CHECK_FALSE(wide->occluded(ray, stats));
        }
    }
}
