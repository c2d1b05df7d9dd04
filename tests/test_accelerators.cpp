// The generic accelerator tests: every structure the registry knows, under every name its bench
// rows use, answers closest-hit and any-hit queries exactly as the brute force does (same
// triangle test, so the same t) on scenes chosen to break structures: a closed mesh, a soup of
// mixed sizes, a flat scene, spheres, degenerate and non-finite primitives, one and no
// primitive. Adding a structure to the registry adds it here.
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/brute_force.h"
#include "framework/accel/grid/grid_accelerator.h"
#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/interface/a3_grid.h"
#include "framework/scene/icosphere_mesh.h"
#include "grader/a4_octree/octree_oracle.h"
#include "grader/kit/test_scenes.h"

#include <doctest/doctest.h>

#include <limits>
#include <set>

using namespace rtlab;
using grader::SceneBuilder;

namespace {

Vec3 randomIn(Pcg32& rng, const Vec3& lower, const Vec3& upper) {
    return lower + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (upper - lower);
}

struct NamedScene {
    const char* name;
    Scene scene;
};

std::vector<NamedScene> scenes() {
    std::vector<NamedScene> list;
    {
        IndexedMesh mesh = icosphereMesh(3);
        SceneBuilder b;
        b.addMesh(mesh.positions, mesh.triangles);
        list.push_back({"icosphere", b.take()});
    }
    {
        SceneBuilder b;
        Pcg32 rng(11, 3);
        const float sizes[] = {0.01f, 0.05f, 0.4f};
        for (int i = 0; i < 600; ++i) {
            Vec3 c = randomIn(rng, Vec3(0.0f), Vec3(1.0f));
            float s = sizes[i % 3];
            b.addTriangle(c + s * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)), c + s * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)),
                          c + s * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)));
        }
        list.push_back({"soup", b.take()});
    }
    list.push_back({"flat", grader::flatScene().scene});  // every box flat in z (GRID-06)
    {
        SceneBuilder b;
        Pcg32 rng(5, 5);
        b.addTriangle({-1, -1, 0}, {5, -1, 0}, {5, 5, 0});
        for (int i = 0; i < 30; ++i) b.addSphere(randomIn(rng, Vec3(0, 0, 0.5f), Vec3(4, 4, 4)), 0.05f + 0.45f * rng.uniform());
        list.push_back({"spheres", b.take()});
    }
    {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        SceneBuilder b;  // degenerate, NaN and infinite vertices among valid triangles
        b.addTriangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {nan, 1, 0});
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {kInfinity, 1, 0});
        b.addTriangle({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
        b.addTriangle({1, 1, -2}, {3, 1, -2}, {1, 3, 1});
        list.push_back({"degenerate", b.take()});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        list.push_back({"one triangle", b.take()});
    }
    list.push_back({"empty", SceneBuilder().take()});
    return list;
}

// Rays from outside and inside the scene's box, axis-aligned ones with +0 and -0 components,
// and segments with a finite tMax.
std::vector<Ray> raysFor(const Scene& scene, uint64_t seed) {
    Bounds3f box;
    for (uint32_t i = 0; i < scene.primitiveCount(); ++i)
        if (isPlaceable(scene.primitiveBounds(i))) box.extend(scene.primitiveBounds(i));
    if (box.isEmpty()) box = Bounds3f(Vec3(-1.0f), Vec3(1.0f));
    Vec3 centre = box.centre(), size = box.diagonal() + Vec3(0.1f);
    Pcg32 rng(seed, 9);
    std::vector<Ray> rays;
    for (int i = 0; i < 1500; ++i) {
        Ray ray;
        ray.origin = i % 3 == 0 ? randomIn(rng, box.lower, box.upper) : centre + 1.5f * randomIn(rng, -size, size);
        Vec3 target = randomIn(rng, box.lower, box.upper);
        ray.direction = target - ray.origin;
        if (i % 5 == 1) ray.direction = Vec3(0.0f, i % 2 ? -0.0f : 0.0f, (i % 4 < 2) ? 1.0f : -1.0f);
        if (i % 7 == 2) ray.direction = Vec3(i % 2 ? -0.0f : 0.0f, 1.0f, 0.0f) * (i % 4 < 2 ? 1.0f : -1.0f);
        if (i % 4 == 3) ray.tMax = 0.5f + rng.uniform();
        if (i % 500 == 0) ray.direction = Vec3(0.0f);  // from inside, tMax = inf: hits nothing, and must end
        rays.push_back(ray);
    }
    return rays;
}

std::vector<std::string> everyRegisteredName() {
    std::vector<std::string> names;
    for (const AcceleratorType* type : acceleratorTypes()) {
        names.push_back(type->name);
        for (const std::string& row : type->benchRows) names.push_back(row);
    }
    return names;
}

}  // namespace

TEST_CASE("every registered structure answers like the brute force") {
    for (NamedScene& named : scenes()) {
        PrimitiveSet primitives(named.scene);
        BruteForce brute;
        brute.build(primitives);
        std::vector<Ray> rays = raysFor(named.scene, 3);
        for (const std::string& name : everyRegisteredName()) {
            CAPTURE(name);
            CAPTURE(named.name);
            AcceleratorSpec spec;
            spec.name = name;
            std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
            accelerator->build(primitives);
            size_t wrong = 0;
            for (const Ray& ray : rays) {
                TraversalStats stats;
                Hit expected = brute.intersect(ray, stats), got = accelerator->intersect(ray, stats);
                bool right = expected.found() == got.found() && (!expected.found() || expected.t == got.t) &&
                             brute.occluded(ray, stats) == accelerator->occluded(ray, stats);
                wrong += right ? 0 : 1;
            }
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("accelerator names: options, defaults, ranges and the older spellings") {
    auto make = [](const std::string& name) {
        AcceleratorSpec spec;
        spec.name = name;
        return makeAccelerator(spec);
    };
    for (const char* valid : {"bvh", "bvh:split=median", "bvh:split=buckets,B=32", "bvh-buckets:2", "bvh-equal", "grid",
                              "grid:C=1", "grid:C=2.5,res=512", "brute"})
        CHECK_NOTHROW(make(valid));
    for (const char* invalid : {"grid:C=0", "grid:C=1001", "grid:res=1.5", "grid:B=12", "grid:C", "bvh:split=magic",
                                "bvh:B=1", "bvh:B=12,B=13", "bvh-median:12", "bvh-magic", "octopus", "brute:C=1"})
        CHECK_THROWS_AS(make(invalid), Error);
    AcceleratorSpec flags{"grid"};
    flags.set("--traversal recursive", "traversal", "recursive");
    CHECK_THROWS_AS(makeAccelerator(flags), Error);  // the grid has no traversal option
    CHECK_THROWS_AS(chooseAccelerator(flags), Error);  // said without making one
    // A flag is typed and checked against the structure's own range, and wins over the name.
    AcceleratorSpec leaf{"bvh:leaf=2"};
    leaf.set("--max-leaf", "leaf", 8);
    CHECK(chooseAccelerator(leaf).parameters.integer("leaf") == 8);
    leaf.set("--max-leaf", "leaf", 0);
    try {
        chooseAccelerator(leaf);
        FAIL("--max-leaf 0 was taken");
    } catch (const Error& e) {
        CHECK(std::string(e.what()) == "--max-leaf 0 is out of range (1..65535)");
    }
    // The help lists every structure with each option's default and range.
    std::string help = acceleratorNames();
    for (const AcceleratorType* type : acceleratorTypes()) {
        CHECK(help.find("  " + type->name + ": ") != std::string::npos);
        for (const AcceleratorOption& o : type->options)
            CHECK(help.find(o.key + "=" + o.rangeText() + " (default " + o.defaultValue + ")") != std::string::npos);
    }
}

TEST_CASE("the fastest structure is one of fast/'s, and only they rank") {
    // This test links fast/, as rtlab-solution does: its render defaults to fast/'s own wide BVH.
    const AcceleratorType* fastest = fastestAcceleratorType();
    REQUIRE(fastest != nullptr);
    CHECK(fastest->name == "fastbvh");
    CHECK(defaultRenderAccelerator() == "fastbvh");
    for (const AcceleratorType* type : acceleratorTypes()) {
        CAPTURE(type->name);
        CHECK(type->speedRank <= fastest->speedRank);
        if (type->name != "bvh4" && type->name != "bvh8" && type->name != "fastbvh") CHECK(type->speedRank == 0);
    }
}

TEST_CASE("the grid's cells hold exactly the primitives whose boxes overlap them") {
    for (NamedScene& named : scenes()) {
        CAPTURE(named.name);
        PrimitiveSet primitives(named.scene);
        for (double c : {1.0, 27.0, 81.0}) {
            GridOptions options;
            options.cellsPerPrimitive = c;
            GridAccelerator accelerator(options, GridInsertion::Box);
            accelerator.build(primitives);
            const UniformGrid& grid = accelerator.grid();
            REQUIRE(grid.cellStart.size() == grid.cellCount() + 1);
            CHECK(grid.cellStart.front() == 0);
            CHECK(grid.cellStart.back() == grid.primIndices.size());
            size_t expectedReferences = 0;
            std::set<std::pair<size_t, uint32_t>> expected;
            for (uint32_t prim = 0; prim < primitives.size(); ++prim) {
                if (!isPlaceable(primitives.bounds(prim))) continue;
                CellRange r = cellRange(grid, primitives.bounds(prim));
                for (int z = r.lower[2]; z <= r.upper[2]; ++z)
                    for (int y = r.lower[1]; y <= r.upper[1]; ++y)
                        for (int x = r.lower[0]; x <= r.upper[0]; ++x, ++expectedReferences) expected.insert({grid.cellIndex({x, y, z}), prim});
            }
            std::set<std::pair<size_t, uint32_t>> found;
            for (size_t cell = 0; cell < grid.cellCount(); ++cell) {
                CHECK(grid.cellStart[cell] <= grid.cellStart[cell + 1]);
                for (uint32_t i = grid.cellStart[cell]; i < grid.cellStart[cell + 1]; ++i) {
                    if (i > grid.cellStart[cell]) CHECK(grid.primIndices[i - 1] < grid.primIndices[i]);
                    found.insert({cell, grid.primIndices[i]});
                }
            }
            CHECK(grid.primIndices.size() == expectedReferences);
            CHECK(found == expected);
        }
    }
}

TEST_CASE("with exact insertion, a grid cell keeps the triangles of its box range that overlap it") {
    for (NamedScene& named : scenes()) {
        CAPTURE(named.name);
        PrimitiveSet primitives(named.scene);
        GridAccelerator boxes(GridOptions{}, GridInsertion::Box), exact(GridOptions{}, GridInsertion::Exact);
        boxes.build(primitives);
        exact.build(primitives);
        const UniformGrid &all = boxes.grid(), &kept = exact.grid();
        REQUIRE(kept.cellStart.size() == all.cellStart.size());
        double slack = grader::overlapSlack(all.bounds);
        size_t wrong = 0, dropped = 0;
        for (int z = 0; z < all.resolution[2]; ++z)
            for (int y = 0; y < all.resolution[1]; ++y)
                for (int x = 0; x < all.resolution[0]; ++x) {
                    size_t c = all.cellIndex({x, y, z});
                    std::set<uint32_t> have(kept.primIndices.begin() + kept.cellStart[c], kept.primIndices.begin() + kept.cellStart[c + 1]);
                    for (uint32_t i = all.cellStart[c]; i < all.cellStart[c + 1]; ++i) {
                        uint32_t prim = all.primIndices[i];
                        // Spheres keep their box's cells; a triangle within rounding of touching may go either way.
                        grader::Overlap o = primitives.triangleCount() <= prim
                                                ? grader::Overlap::Yes
                                                : grader::triangleBoxOverlap(primitives.triangle(prim), gridCellBox(all, {x, y, z}), slack);
                        if (o != grader::Overlap::Unsure) wrong += have.count(prim) != (o == grader::Overlap::Yes) ? 1 : 0;
                        dropped += have.count(prim) ? 0 : 1;
                    }
                }
        CHECK(wrong == 0);
        CHECK(kept.primIndices.size() + dropped == all.primIndices.size());
    }
}
