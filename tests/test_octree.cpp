// The octree of the reference solution (assignment a4) against the grader's own oracles: its
// triangle-box test against the double-precision separating-axis test, its build against the
// structure check, its walk against the exact leaf order, and the octree cases of the stress
// catalogue (docs/conventions.md#stress-catalogue, OCT-01 .. OCT-05).
#include "framework/accel/brute_force.h"
#include "framework/accel/octree/octree_accelerator.h"
#include "framework/core/pcg32.h"
#include "framework/interface/a4_octree.h"
#include "framework/render/renderer.h"
#include "framework/scene/camera.h"
#include "grader/octree_oracle.h"
#include "grader/octree_structure.h"
#include "grader/octree_visit_order.h"
#include "grader/test_scenes.h"
#include "tests/icosphere_fixture.h"

#include <doctest/doctest.h>


using namespace rtlab;
using grader::SceneBuilder;

namespace {

Vec3 randomIn(Pcg32& rng, const Vec3& lower, const Vec3& upper) {
    return lower + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (upper - lower);
}

Ray makeRay(Vec3 o, Vec3 d) {
    Ray r;
    r.origin = o;
    r.direction = d;
    return r;
}

struct Built {
    Scene scene;
    PrimitiveSet primitives;
    OctreeAccelerator octree;

    Built(Scene s, const OctreeOptions& options) : scene(std::move(s)), primitives(scene), octree(options) { octree.build(primitives); }
};

Scene soup(int count, uint64_t seed) {
    SceneBuilder b;
    Pcg32 rng(seed, 3);
    const float sizes[] = {0.01f, 0.05f, 0.4f};
    for (int i = 0; i < count; ++i) {
        Vec3 c = randomIn(rng, Vec3(0.0f), Vec3(1.0f));
        float s = sizes[i % 3];
        b.addTriangle(c + s * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)), c + s * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)),
                      c + s * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)));
    }
    for (int i = 0; i < 10; ++i) b.addSphere(randomIn(rng, Vec3(0.0f), Vec3(1.0f)), 0.02f + 0.1f * rng.uniform());
    return b.take();
}

Scene icosphereScene(int levels) {
    testing::IndexedMesh mesh = testing::icosphere(levels);
    SceneBuilder b;
    b.addMesh(mesh.positions, mesh.triangles);
    return b.take();
}

// Rays from around and inside the root, every fifth with a zero component of either sign.
std::vector<Ray> raysAround(const Bounds3f& box, uint64_t seed, int count) {
    Pcg32 rng(seed, 11);
    Vec3 size = box.diagonal();
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        Vec3 o = i % 3 == 0 ? randomIn(rng, box.lower, box.upper) : randomIn(rng, box.lower - size, box.upper + size);
        Ray r = makeRay(o, randomIn(rng, box.lower, box.upper) - o);
        if (i % 5 == 1) r.direction[i % 3] = i % 2 ? -0.0f : 0.0f;
        rays.push_back(r);
    }
    return rays;
}

}  // namespace

TEST_CASE("triangleOverlapsBox agrees with the double-precision separating-axis test") {
    Pcg32 rng(7, 1);
    size_t graded = 0, wrong = 0;
    for (int i = 0; i < 200000; ++i) {
        Bounds3f box(randomIn(rng, Vec3(-1.0f), Vec3(1.0f)), randomIn(rng, Vec3(-1.0f), Vec3(1.0f)));
        // Small triangles near the box's faces, long thin ones across it, large ones around it.
        float size = i % 3 == 0 ? 0.1f : i % 3 == 1 ? 2.0f : 0.5f;
        Vec3 c = randomIn(rng, box.lower - Vec3(0.3f), box.upper + Vec3(0.3f));
        std::array<Vec3, 3> t{c + size * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)), c + size * randomIn(rng, Vec3(-1.0f), Vec3(1.0f)),
                              c + size * randomIn(rng, Vec3(-1.0f), Vec3(1.0f))};
        if (i % 7 == 0) t[2] = t[1];  // a segment
        grader::Overlap expected = grader::triangleBoxOverlap(t, box, grader::overlapSlack(box));
        if (expected == grader::Overlap::Unsure) continue;
        ++graded;
        wrong += triangleOverlapsBox(t[0], t[1], t[2], box) != (expected == grader::Overlap::Yes) ? 1 : 0;
    }
    CHECK(graded > 190000);
    CHECK(wrong == 0);
}

TEST_CASE("the reference octree passes the grader's structure check") {
    for (OctreeInsertion insertion : {OctreeInsertion::Exact, OctreeInsertion::Box}) {
        for (int maxPrims : {1, 4, 8}) {
            OctreeOptions options;
            options.insertion = insertion;
            options.maxPrims = uint32_t(maxPrims);
            for (Scene scene : {icosphereScene(3), soup(800, 5)}) {
                Built built(std::move(scene), options);
                grader::OctreeStructureReport report = grader::checkOctreeStructure(built.octree.octree(), built.scene, options);
                CAPTURE(maxPrims);
                CAPTURE(report.problems.empty() ? std::string() : report.problems.front());
                CHECK(report.problemCount == 0);
                CHECK(report.leaves > 1);
            }
        }
    }
}

TEST_CASE("the reference walk visits the leaves in the exact front-to-back order") {
    OctreeOptions options;
    options.maxPrims = 4;
    Built built(soup(1500, 9), options);
    const Octree& octree = built.octree.octree();
    std::vector<Ray> rays = raysAround(octree.root, 3, 2000);
    std::vector<std::vector<uint32_t>> entered(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        TraversalStats stats;
        Traversal traversal(built.primitives, rays[i], stats);
        traversal.listLeavesIn(&entered[i]);
        Hit hit;
        hit.t = rays[i].tMax;
        intersectOctree(octree, traversal, hit);
    }
    grader::VisitOrderVerdict verdict = grader::judgeOctreeVisits(octree, built.scene, rays, entered);
    CAPTURE(verdict.problems.empty() ? std::string() : verdict.problems.front());
    MESSAGE(verdict.graded << " of " << rays.size() << " rays graded");
    CHECK(verdict.graded > rays.size() / 2);
    CHECK(verdict.wrong == 0);
}

namespace {

// The unit cube forced as the root by two small anchor triangles in opposite corners; the
// cases' own triangles follow them (ids 2, 3, ...).
SceneBuilder unitCube() {
    SceneBuilder b;
    b.addTriangle({0, 0, 0}, {0.0625f, 0, 0}, {0, 0.0625f, 0});
    b.addTriangle({1, 1, 1}, {0.9375f, 1, 1}, {1, 0.9375f, 1});
    return b;
}

struct StressRay {
    const char* id;
    Ray ray;
    uint32_t prim;  // kNoHit: a miss
    float t;
};

void checkStress(Scene scene, const std::vector<StressRay>& cases) {
    OctreeOptions options;
    options.maxPrims = 1;  // every node with two triangles is split: the walk crosses many leaves
    Built built(std::move(scene), options);
    REQUIRE(built.octree.octree().root == Bounds3f(Vec3(0.0f), Vec3(1.0f)));
    for (const StressRay& c : cases) {
        CAPTURE(c.id);
        TraversalStats stats;
        Hit hit = built.octree.intersect(c.ray, stats);
        CHECK(hit.prim == c.prim);
        if (c.prim != kNoHit) CHECK(hit.t == doctest::Approx(c.t).epsilon(1e-6));
        CHECK(built.octree.occluded(c.ray, stats) == (c.prim != kNoHit));
    }
}

}  // namespace

// Expected hits by hand: t = distance along d to the plane of the triangle hit.
TEST_CASE("OCT-01, OCT-02: rays on a mid-plane and axis-parallel rays with a zero component of either sign") {
    SceneBuilder b = unitCube();
    b.addTriangle({0.25f, 0, 0.75f}, {0.75f, 0, 0.75f}, {0.5f, 0.5f, 0.75f});   // 2: OCT-01's X, across x = 0.5
    b.addTriangle({0.4f, 0.4f, 0.5f}, {0.6f, 0.4f, 0.5f}, {0.4f, 0.6f, 0.5f});  // 3: under (0.49, 0.49) at z = 0.5
    checkStress(b.take(), {
        {"OCT-01 d = (+0, 0, 1) in the plane x = 0.5", makeRay({0.5f, 0.25f, -1}, {0, 0, 1}), 2, 1.75f},
        {"OCT-01 d = (-0, 0, 1)", makeRay({0.5f, 0.25f, -1}, {-0.0f, 0, 1}), 2, 1.75f},
        {"OCT-01 d = (-0, -0, 1)", makeRay({0.5f, 0.25f, -1}, {-0.0f, -0.0f, 1}), 2, 1.75f},
        {"OCT-02 (0.49, 0.49, -1) along (0, 0, 2)", makeRay({0.49f, 0.49f, -1}, {0, 0, 2}), 3, 0.75f},
        {"OCT-02 (0.49, 0.49, 2) along (0, 0, -2): past the X (x < 0.495 there)", makeRay({0.49f, 0.49f, 2}, {0, 0, -2}), 3, 0.75f},
        {"OCT-02 (0.49, 0.49, 2) along (-0, -0, -2)", makeRay({0.49f, 0.49f, 2}, {-0.0f, -0.0f, -2}), 3, 0.75f},
        {"OCT-02 along -x through (0.49, 0.49): nothing in its way", makeRay({2, 0.49f, 0.49f}, {-1, 0, 0}), kNoHit, 0},
    });
}

TEST_CASE("OCT-03: an origin inside a leaf, with triangles ahead of and behind it") {
    SceneBuilder b = unitCube();
    b.addTriangle({0.2f, 0.2f, 0.1f}, {0.4f, 0.2f, 0.1f}, {0.2f, 0.4f, 0.1f});  // 2: behind for +z
    b.addTriangle({0.2f, 0.2f, 0.9f}, {0.4f, 0.2f, 0.9f}, {0.2f, 0.4f, 0.9f});  // 3: ahead for +z
    checkStress(b.take(), {
        {"OCT-03 +z from (0.25, 0.25, 0.3)", makeRay({0.25f, 0.25f, 0.3f}, {0, 0, 1}), 3, 0.6f},
        {"OCT-03 -z from (0.25, 0.25, 0.3)", makeRay({0.25f, 0.25f, 0.3f}, {0, 0, -1}), 2, 0.2f},
        {"OCT-03 -z, -0 in x and y", makeRay({0.25f, 0.25f, 0.3f}, {-0.0f, -0.0f, -1}), 2, 0.2f},
        {"OCT-03 diagonal (1, 1, 4) from inside", makeRay({0.25f, 0.25f, 0.3f}, {0.0625f, 0.0625f, 1}), 3, 0.6f},
    });
}

TEST_CASE("OCT-05: a ray in a mid-plane meets a triangle that only touches that plane") {
    // Triangle 2 lies in y = 0.625, left of x = 0.5, with its edge on x = 0.5; triangle 3 is its
    // mirror image right of it, farther along the ray. Inclusive insertion puts each in the
    // leaves on both sides of the plane, so the walk finds 2 whichever side -0 or +0 sends it.
    SceneBuilder b = unitCube();
    b.addTriangle({0.25f, 0.625f, 0.25f}, {0.5f, 0.625f, 0.25f}, {0.5f, 0.625f, 0.375f});
    b.addTriangle({0.75f, 0.75f, 0.25f}, {0.5f, 0.75f, 0.25f}, {0.5f, 0.75f, 0.375f});
    checkStress(b.take(), {
        {"OCT-05 d = (+0, 1, 0)", makeRay({0.5f, 0, 0.3125f}, {0, 1, 0}), 2, 0.625f},
        {"OCT-05 d = (-0, 1, 0)", makeRay({0.5f, 0, 0.3125f}, {-0.0f, 1, 0}), 2, 0.625f},
        {"OCT-05 d = (-0, -1, +0) from above", makeRay({0.5f, 1, 0.3125f}, {-0.0f, -1, 0}), 3, 0.25f},
    });
}

TEST_CASE("OCT-04: the same rays in all eight direction octants hit what the brute force hits") {
    Scene scene = soup(600, 21);
    PrimitiveSet primitives(scene);
    BruteForce brute;
    brute.build(primitives);
    OctreeOptions options;
    options.maxPrims = 2;
    OctreeAccelerator octree(options);
    octree.build(primitives);
    Pcg32 rng(4, 4);
    size_t wrong = 0;
    for (int i = 0; i < 300; ++i) {
        Vec3 o = randomIn(rng, Vec3(0.2f), Vec3(0.8f)), d = randomIn(rng, Vec3(0.1f), Vec3(1.0f));
        for (int octant = 0; octant < 8; ++octant) {
            Ray ray = makeRay(o, Vec3(octant & 4 ? -d.x : d.x, octant & 2 ? -d.y : d.y, octant & 1 ? -d.z : d.z));
            TraversalStats stats;
            Hit expected = brute.intersect(ray, stats), got = octree.intersect(ray, stats);
            wrong += expected.found() != got.found() || (expected.found() && expected.t != got.t) ? 1 : 0;
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("the memory rule: 70000 copies of one triangle make one leaf") {
    // BVH-11's scene: the triangle lies in the root's mid-plane z = 0 and reaches into every
    // child, so every child would get all 70000: splitting would only copy them.
    for (OctreeInsertion insertion : {OctreeInsertion::Exact, OctreeInsertion::Box}) {
        SceneBuilder b;
        for (int i = 0; i < 70000; ++i) b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        OctreeOptions options;
        options.insertion = insertion;
        Built built(b.take(), options);
        CHECK(built.octree.octree().nodes.size() == 1);
        CHECK(built.octree.octree().primIndices.size() == 70000);
        TraversalStats stats;
        CHECK(built.octree.intersect(makeRay({0.25f, 0.25f, 1}, {0, 0, -1}), stats).t == 1.0f);
    }
}

TEST_CASE("the steps AOV counts the octree leaves each camera ray enters") {
    Scene scene = icosphereScene(3);
    PrimitiveSet primitives(scene);
    OctreeOptions options;
    options.maxPrims = 2;
    OctreeAccelerator octree(options);
    octree.build(primitives);
    Camera camera;
    camera.position = DVec3(0.3, 0.2, 4.0);
    RenderSettings settings;
    settings.width = 24;
    settings.height = 18;
    settings.aovs = {Aov::Steps};
    settings.progress = false;
    RenderResult result = Renderer(scene, camera, octree).render(settings);
    size_t entering = 0;
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
            Ray ray = camera.generateRay(x, y, settings.width, settings.height);
            std::vector<uint32_t> leaves;
            TraversalStats stats;
            Traversal traversal(primitives, ray, stats);
            traversal.listLeavesIn(&leaves);
            Hit hit;
            intersectOctree(octree.octree(), traversal, hit);
            CHECK(result.aovs.steps[size_t(y) * settings.width + x] == leaves.size());
            entering += leaves.empty() ? 0 : 1;
        }
    CHECK(entering > 100);
    CHECK(maxCount(result.aovs.steps) > 1);
}
