// The tuned grid of fast/ (fastgrid): its counting sort fills exactly the cells a3's textbook
// fillGridCells fills, and its walk visits the cells, tests the primitives, skips the repeats
// and returns the hits of the textbook intersectGrid, ray for ray. Correctness against the brute
// force is in test_accelerators.cpp, as for every registered structure.
#include "fast/grid_cell_sort.h"
#include "framework/accel/accelerator.h"
#include "framework/core/pcg32.h"
#include "framework/interface/a3_grid.h"
#include "framework/scene/benchmark_rays.h"
#include "framework/scene/benchmark_scenes.h"
#include "grader/kit/test_scenes.h"
#include "tests/built_accelerator.h"
#include "tests/fetched_models.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <string>

using namespace rtlab;
using grader::SceneBuilder;

namespace {

Vec3 randomIn(Pcg32& rng, const Vec3& lower, const Vec3& upper) {
    return lower + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (upper - lower);
}

// Triangles of one size scattered through the unit cube: small ones fill at most two cells per
// axis (the sort's branch-free path), big ones many (its loops).
Scene soup(int count, float size, uint64_t seed) {
    SceneBuilder b;
    Pcg32 rng(seed, 1);
    for (int i = 0; i < count; ++i) {
        Vec3 c = randomIn(rng, Vec3(0.0f), Vec3(1.0f));
        b.addTriangle(c + size * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)), c + size * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)),
                      c + size * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)));
    }
    return b.take();
}

void checkSameCells(const Scene& scene, const GridOptions& options) {
    PrimitiveSet primitives(scene);
    UniformGrid textbook = gridFrame(primitives.allBounds(), options);
    fillGridCells(textbook, primitives.allBounds());
    GridCells sorted = sortIntoCells(textbook, primitives.allBounds());
    CHECK(std::equal(sorted.cellStart.begin(), sorted.cellStart.end(), textbook.cellStart.begin(), textbook.cellStart.end()));
    CHECK(std::equal(sorted.primIndices.begin(), sorted.primIndices.end(), textbook.primIndices.begin(),
                     textbook.primIndices.end()));
}

std::unique_ptr<Accelerator> built(const std::string& name, const PrimitiveSet& primitives) {
    return builtAccelerator({name}, primitives);
}

// Closest hits and their work, ray by ray, against the textbook grid over the same cells.
void checkSameWalk(const Scene& scene, const std::vector<Ray>& rays) {
    PrimitiveSet primitives(scene);
    auto textbook = built("grid", primitives), fast = built("fastgrid", primitives);
    size_t differentHits = 0, differentWork = 0, differentAnyHits = 0;
    for (const Ray& ray : rays) {
        TraversalStats a, b;
        Hit expected = textbook->intersect(ray, a), got = fast->intersect(ray, b);
        differentHits += expected.t == got.t && expected.prim == got.prim && expected.b1 == got.b1 ? 0 : 1;
        differentWork += a.nodeVisits == b.nodeVisits && a.cellSteps == b.cellSteps && a.primitiveTests == b.primitiveTests &&
                                 a.mailboxRepeats == b.mailboxRepeats
                             ? 0
                             : 1;
        TraversalStats ignored;
        differentAnyHits += textbook->occluded(ray, ignored) == fast->occluded(ray, ignored) ? 0 : 1;
    }
    CHECK(differentHits == 0);
    CHECK(differentWork == 0);
    CHECK(differentAnyHits == 0);
}

}  // namespace

TEST_CASE("the counting sort fills the cells fillGridCells fills, bit for bit") {
    GridOptions defaults;
    SUBCASE("small triangles, each in at most two cells per axis") { checkSameCells(soup(5000, 0.01f, 3), defaults); }
    SUBCASE("big triangles spanning many cells") { checkSameCells(soup(800, 0.3f, 4), defaults); }
    SUBCASE("a coarse and a fine rule") {
        for (double c : {1.0, 81.0}) {
            GridOptions options;
            options.cellsPerPrimitive = c;
            checkSameCells(soup(3000, 0.05f, 5), options);
        }
    }
    SUBCASE("the bunny") { checkSameCells(loadFetchedModel("bunny.gltf"), defaults); }
    SUBCASE("a flat scene (one layer)") { checkSameCells(grader::flatScene().scene, defaults); }
    SUBCASE("NaN, infinite and degenerate boxes go nowhere") {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {nan, 1, 0});
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {kInfinity, 1, 0});
        b.addTriangle({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
        checkSameCells(b.take(), defaults);
    }
    SUBCASE("one triangle, and none") {
        SceneBuilder one;
        one.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        checkSameCells(one.take(), defaults);
        checkSameCells(SceneBuilder().take(), defaults);
    }
    SUBCASE("references too wide for 32-bit words") {
        // 1024 x 1024 cells in one layer need 20 bits, 5000 primitives 13: the 64-bit path.
        SceneBuilder b;
        Pcg32 rng(8, 2);
        for (int i = 0; i < 5000; ++i) {
            Vec3 c = randomIn(rng, Vec3(0.0f), Vec3(1.0f, 1.0f, 0.0f));
            b.addTriangle(c, c + Vec3(0.002f, 0.0f, 0.0f), c + Vec3(0.0f, 0.002f, 0.0f));
        }
        GridOptions options;
        options.cellsPerPrimitive = 1000.0;
        options.maxResolution = 1024;
        checkSameCells(b.take(), options);
    }
}

TEST_CASE("fastgrid walks the textbook grid's cells and reports its hits and its work") {
    Scene bunny = loadFetchedModel("bunny.gltf");
    SUBCASE("bunny, primary and incoherent rays") {
        std::vector<Ray> rays = makeBenchmarkRays(RayKind::Primary, bunny.bounds());
        std::vector<Ray> incoherent = makeBenchmarkRays(RayKind::Incoherent, bunny.bounds());
        std::vector<Ray> every64th;
        for (size_t i = 0; i < rays.size(); i += 64) every64th.push_back(rays[i]);
        for (size_t i = 0; i < incoherent.size(); i += 64) every64th.push_back(incoherent[i]);
        checkSameWalk(bunny, every64th);
    }
    SUBCASE("the teapot in a stadium") {
        Scene stadium = sceneFromMesh(teapotInAStadium(bunny), "stadium");
        std::vector<Ray> rays = makeBenchmarkRays(RayKind::Primary, bunny.bounds());
        std::vector<Ray> every256th;
        for (size_t i = 0; i < rays.size(); i += 256) every256th.push_back(rays[i]);
        checkSameWalk(stadium, every256th);
    }
    SUBCASE("segments with a finite tMax, and axis-aligned rays with both zeros") {
        Scene scene = soup(2000, 0.05f, 6);
        Pcg32 rng(9, 9);
        std::vector<Ray> rays;
        for (int i = 0; i < 2000; ++i) {
            Ray ray;
            ray.origin = randomIn(rng, Vec3(-0.5f), Vec3(1.5f));
            ray.direction = randomIn(rng, Vec3(0.0f), Vec3(1.0f)) - ray.origin;
            if (i % 4 == 1) ray.direction = Vec3(0.0f, i % 8 == 1 ? -0.0f : 0.0f, 1.0f);
            if (i % 3 == 2) ray.tMax = 0.3f + rng.uniform();
            rays.push_back(ray);
        }
        checkSameWalk(scene, rays);
    }
}
