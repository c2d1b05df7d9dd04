// The fast BVH of fast/ (fastbvh: wide_bvh_builder.h with the wide traversal): the same tree on
// any number of threads, leaves that fill their packets, memory within the bound, and an
// any-hit query that agrees with the closest-hit query on every ray. Its hits against the
// oracle (test scenes, random rays, edge and vertex rays, no leak through shared edges) are in
// test_bvh.cpp, with every other accelerator's.
#include "fast/wide_bvh_builder.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/core/pcg32.h"
#include "framework/scene/benchmark_rays.h"
#include "tests/built_accelerator.h"
#include "tests/fetched_models.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>

using namespace rtlab;

namespace {

std::unique_ptr<Accelerator> built(const std::string& name, const PrimitiveSet& prims) { return builtAccelerator({name}, prims); }

// Leaves and the packets of four their triangles fill.
struct LeafCount {
    size_t leaves = 0, packets = 0;
};

LeafCount leavesOf(const StructureView& view) {
    LeafCount count;
    for (const StructureNode& node : view.nodes)
        if (node.childCount == 0) {
            ++count.leaves;
            count.packets += (node.primCount + 3) / 4;
        }
    return count;
}

}  // namespace

TEST_CASE("the fast BVH's tree does not depend on the number of build threads") {
    Scene scene = loadFetchedModel("engine.glb");
    PrimitiveSet prims(scene);
    for (std::string width : {"4", "8"}) {
        CAPTURE(width);
        std::string name = "fastbvh:width=" + width;
        StructureView one = built(name + ",threads=1", prims)->structure();
        for (std::string threads : {"2", "3"}) {
            CAPTURE(threads);
            // Nodes are numbered as threads reach them, so compare the trees as the view walks them.
            StructureView many = built(name + ",threads=" + threads, prims)->structure();
            REQUIRE(many.nodes.size() == one.nodes.size());
            int different = 0;
            for (size_t i = 0; i < one.nodes.size(); ++i)
                different += !(one.nodes[i].bounds == many.nodes[i].bounds) ||
                             one.nodes[i].childCount != many.nodes[i].childCount ||
                             one.nodes[i].primCount != many.nodes[i].primCount;
            CHECK(different == 0);
            CHECK(one.primIndices == many.primIndices);
        }
    }
}

TEST_CASE("the fast BVH's leaves fill their packets, and its memory stays within 80 bytes per triangle") {
    for (std::string file : {"bunny.gltf", "engine.glb"}) {
        CAPTURE(file);
        Scene scene = loadFetchedModel(file.c_str());
        PrimitiveSet prims(scene);
        for (std::string width : {"4", "8"}) {
            CAPTURE(width);
            auto fast = built("fastbvh:width=" + width, prims);
            auto folded = built("bvh" + width + "-buckets:12", prims);
            LeafCount own = leavesOf(fast->structure()), student = leavesOf(folded->structure());
            CAPTURE(own.packets);
            CAPTURE(student.packets);
            // The student's SAH makes leaves of about two triangles, half of each packet padding.
            CHECK(double(prims.size()) / double(own.packets * 4) > 0.75);
            CHECK(own.packets * 4 < student.packets * 3);
            CHECK(double(fast->memoryBytes()) / prims.size() <= 80.0);
        }
    }
}

TEST_CASE("the fast BVH's any-hit query agrees with its closest-hit query on every ray") {
    for (std::string file : {"bunny.gltf", "engine.glb"}) {
        CAPTURE(file);
        Scene scene = loadFetchedModel(file.c_str());
        PrimitiveSet prims(scene);
        Bounds3f bounds = scene.bounds();
        for (std::string width : {"4", "8"}) {
            CAPTURE(width);
            auto fast = built("fastbvh:width=" + width, prims);
            TraversalStats stats;
            int disagree = 0, segmentsDisagree = 0;
            for (RayKind kind : {RayKind::Primary, RayKind::Incoherent}) {
                std::vector<Ray> rays = makeBenchmarkRays(kind, bounds);
                for (size_t i = 0; i < rays.size(); i += 13) {
                    Ray ray = rays[i];
                    Hit hit = fast->intersect(ray, stats);
                    disagree += fast->occluded(ray, stats) != hit.found();
                    if (!hit.found()) continue;
                    // Segments that end at the hit or just before it. (Ending exactly at the hit, both
                    // may miss it: a0's slab test rounds a box's near distance, not outwards.)
                    for (float end : {hit.t, hit.t * 0.999f}) {
                        ray.tMax = end;
                        segmentsDisagree += fast->occluded(ray, stats) != fast->intersect(ray, stats).found();
                    }
                }
            }
            CHECK(disagree == 0);
            CHECK(segmentsDisagree == 0);
        }
    }
}

TEST_CASE("the fast BVH's builder rejects options out of range") {
    std::vector<Bounds3f> boxes(3, Bounds3f(Vec3(0.0f), Vec3(1.0f)));
    WideBvhBuildOptions options;
    options.bins = 1;
    CHECK_THROWS(buildWideBvh<8>(boxes, options));
    options.bins = kMaxSahBins + 1;
    CHECK_THROWS(buildWideBvh<4>(boxes, options));
    CHECK(buildWideBvh<4>({}, WideBvhBuildOptions{}).nodes.empty());
}

TEST_CASE("every structure fast/ registers is named for the executables that leave fast/ out") {
    // The framework's own structures (framework/accel/*); every other one came from fast/.
    const std::vector<std::string> framework{"brute", "bvh", "grid", "grid2", "octree", "kdtree", "bsp"};
    size_t fromFast = 0;
    for (const AcceleratorType* type : acceleratorTypes()) {
        if (std::find(framework.begin(), framework.end(), type->name) != framework.end()) continue;
        ++fromFast;
        CAPTURE(type->name);
        CHECK(whereAcceleratorIs(type->name) != nullptr);
    }
    CHECK(fromFast >= 4);  // bvh4, bvh8, fastbvh, fastgrid
}
