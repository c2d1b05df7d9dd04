// The scene seen from a point (fast/point_view.h), against the wide BVH, on the bunny and the
// engine from 24 points on every side and at several distances: every shadow ray toward the
// point answered the same, from surface points offset as the renderer offsets them, from
// triangles' corners and edges (where shared edges leak), from anywhere and from far beyond the
// scene; every ray from the point finding the same hit; rays of other kinds go to the BVH; it
// declines what it cannot be sure of; and a render through it is the textbook BVH's image to
// the bit.
#include "fast/point_view.h"
#include "framework/accel/accelerator.h"
#include "framework/core/pcg32.h"
#include "framework/render/renderer.h"
#include "framework/render/spawn_ray.h"
#include "framework/scene/benchmark_rays.h"
#include "tests/built_accelerator.h"
#include "tests/fetched_models.h"

#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

std::unique_ptr<Accelerator> built(const std::string& name, const PrimitiveSet& prims) { return builtAccelerator({name}, prims); }

// Points around the bounds: along each axis both ways and along diagonals, from just beyond
// the bounds to far away.
std::vector<Vec3> pointsAround(const Bounds3f& bounds) {
    std::vector<Vec3> lights;
    const Vec3 centre = bounds.centre();
    const float size = glm::length(bounds.diagonal());
    const Vec3 directions[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0.6f, 0.7f, -0.4f}, {-0.3f, 0.8f, 0.5f}};
    for (const Vec3& d : directions)
        for (float distance : {1.2f, 3.0f, 20.0f}) lights.push_back(centre + distance * size * glm::normalize(d));
    return lights;
}

// A point on an edge of a random triangle, s of the way from its corner i % 3 to the next.
Vec3 edgePoint(const PrimitiveSet& prims, Pcg32& rng, int i, float s) {
    const auto& triangle = prims.triangle(uint32_t(rng.uniform() * prims.triangleCount()) % prims.triangleCount());
    return (1.0f - s) * triangle[i % 3] + s * triangle[(i + 1) % 3];
}

Vec3 pointIn(const Bounds3f& bounds, Pcg32& rng) {
    return bounds.lower + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * bounds.diagonal();
}

// Half through an edge point of a triangle, half through any point of the bounds.
Vec3 edgeOrAnywhere(const PrimitiveSet& prims, const Bounds3f& bounds, Pcg32& rng, int i) {
    float s = rng.uniform();
    Vec3 anywhere = pointIn(bounds, rng);
    return i % 2 ? edgePoint(prims, rng, i, s) : anywhere;
}

// The segment from origin toward the point, as the renderer's shadow rays are made.
Ray toward(const Vec3& point, const Vec3& origin, float tMin = kShadowEpsilon, float tMax = 1.0f - kShadowEpsilon) {
    Ray ray;
    ray.origin = origin;
    ray.direction = point - origin;
    ray.tMin = tMin;
    ray.tMax = tMax;
    return ray;
}

struct Tally {
    int rays = 0, blocked = 0, disagree = 0;
    void add(bool view, bool bvh) {
        ++rays;
        blocked += bvh;
        disagree += view != bvh;
    }
};

}  // namespace

// The fast BVH over a fetched model.
struct Model {
    Scene scene;
    PrimitiveSet prims;
    Bounds3f bounds;
    std::unique_ptr<Accelerator> fast;

    explicit Model(const char* file)
        : scene(loadFetchedModel(file)), prims(scene), bounds(scene.bounds()), fast(built("fastbvh", prims)) {}
};

// Calls check(model) for the bunny and the engine.
template <typename Check>
void eachModel(Check&& check) {
    for (const char* file : {"bunny.gltf", "engine.glb"}) {
        CAPTURE(file);
        check(Model(file));
    }
}

// Calls check(point, view) for every point around the model (pointsAround) that gets a view:
// at least 16 of the 24 must (the others are too near a triangle, or beside the bounds).
template <typename Check>
void eachView(const Model& model, Check&& check) {
    int made = 0;
    for (const Vec3& point : pointsAround(model.bounds)) {
        CAPTURE(point);
        std::unique_ptr<PointQueries> view = model.fast->queriesAt(point);
        if (!view) continue;
        ++made;
        check(point, *view);
    }
    CHECK(made >= 16);
}

TEST_CASE("point view: every shadow ray answered as the wide BVH answers it") {
    eachModel([](const Model& model) {
        const PrimitiveSet& prims = model.prims;
        const Bounds3f& bounds = model.bounds;
        const Accelerator& fast = *model.fast;
        std::vector<Ray> cameraRays = makeBenchmarkRays(RayKind::Primary, bounds);
        Pcg32 rng(3, 4);
        eachView(model, [&](const Vec3& light, const PointQueries& view) {
            TraversalStats stats;
            Tally fromSurfaces, fromCorners, fromAnywhere, fromBeyond;
            // The renderer's shadow rays: from hit points, offset off the surface.
            for (size_t i = 0; i < cameraRays.size(); i += 97) {
                Hit hit = fast.intersect(cameraRays[i], stats);
                if (!hit.found()) continue;
                SurfaceHit surface = model.scene.surfaceAt(cameraRays[i], hit);
                Ray ray = spawnShadowRay(surface.point, surface.pointError, surface.geometricNormal, light);
                fromSurfaces.add(view.occluded(ray, stats), fast.occluded(ray, stats));
            }
            // From corners and edge points of triangles, not offset: rays that graze their own
            // triangle and its neighbours, through shared edges.
            for (int i = 0; i < 3000; ++i) {
                Vec3 origin = edgePoint(prims, rng, i, rng.uniform() < 0.5f ? 0.0f : rng.uniform());
                for (Ray ray : {toward(light, origin), toward(light, origin, 0.0f, 1.0f)})
                    fromCorners.add(view.occluded(ray, stats), fast.occluded(ray, stats));
            }
            // From anywhere in and around the bounds.
            for (int i = 0; i < 3000; ++i) {
                Vec3 t(rng.uniform(), rng.uniform(), rng.uniform());
                Ray ray = toward(light, bounds.lower - 0.1f * bounds.diagonal() + 1.2f * t * bounds.diagonal());
                fromAnywhere.add(view.occluded(ray, stats), fast.occluded(ray, stats));
            }
            // From far beyond the scene, through it toward the light: the rounding of these rays'
            // directions moves them by a sizeable part of a cell near the light, which the
            // margins must cover.
            for (int i = 0; i < 3000; ++i) {
                Vec3 target = edgeOrAnywhere(prims, bounds, rng, i);
                Ray ray = toward(light, light + (50.0f + 2000.0f * rng.uniform()) * (target - light), 0.0f, 1.0f);
                fromBeyond.add(view.occluded(ray, stats), fast.occluded(ray, stats));
            }
            CHECK(fromSurfaces.disagree == 0);
            CHECK(fromCorners.disagree == 0);
            CHECK(fromAnywhere.disagree == 0);
            CHECK(fromBeyond.disagree == 0);
            // Not vacuous: some rays of each kind are blocked and some are not.
            for (const Tally* tally : {&fromSurfaces, &fromCorners, &fromAnywhere, &fromBeyond}) {
                CHECK(tally->blocked > 0);
                CHECK(tally->blocked < tally->rays);
            }
        });
    });
}

TEST_CASE("point view: every ray from the point hits what the wide BVH's ray hits") {
    eachModel([](const Model& model) {
        const PrimitiveSet& prims = model.prims;
        const Bounds3f& bounds = model.bounds;
        const Accelerator& fast = *model.fast;
        Pcg32 rng(8, 2);
        eachView(model, [&](const Vec3& eye, const PointQueries& view) {
            TraversalStats stats;
            int rays = 0, hits = 0, differ = 0, nearer = 0;
            for (int i = 0; i < 6000; ++i) {
                // Toward any point of the bounds, or through a triangle's edge; the direction of
                // any length, some segments cut short.
                Vec3 target = edgeOrAnywhere(prims, bounds, rng, i);
                Ray ray;
                ray.origin = eye;
                ray.direction = (0.05f + 20.0f * rng.uniform()) * glm::normalize(target - eye);
                if (i % 5 == 0) ray.tMax = rng.uniform() * glm::length(target - eye) / glm::length(ray.direction);
                Hit ours = view.intersect(ray, stats), bvh = fast.intersect(ray, stats);
                ++rays;
                hits += bvh.found();
                // The same distance (of equally near triangles perhaps another one), or a hit a
                // few ulps nearer: the BVH prunes a box whose near distance a0's slab test
                // rounds up past a hit an ulp nearer than the one it has, and the view, which
                // tests every triangle in its cell, finds that one.
                if (ours.found() && bvh.found() && ours.t < bvh.t && bvh.t - ours.t <= 1e-6f * bvh.t) ++nearer;
                else differ += ours.found() != bvh.found() || ours.t != bvh.t;
            }
            CHECK(differ == 0);
            CHECK(nearer <= rays / 1000);
            CHECK(hits > rays / 10);
            CHECK(hits < rays);
        });
    });
}

TEST_CASE("point view: rays neither from nor toward its point are the BVH's, and it declines what it cannot be sure of") {
    Scene scene = loadFetchedModel("bunny.gltf");
    PrimitiveSet prims(scene);
    const Bounds3f bounds = scene.bounds();
    auto fast = built("fastbvh", prims);
    const Vec3 light = bounds.centre() + 3.0f * bounds.diagonal();
    std::unique_ptr<PointQueries> view = fast->queriesAt(light);
    REQUIRE(view);
    TraversalStats stats;
    int disagree = 0;
    for (const Ray& ray : makeBenchmarkRays(RayKind::Incoherent, bounds)) {
        Ray segment = ray;
        segment.tMax = 0.5f * glm::length(bounds.diagonal());
        disagree += view->occluded(segment, stats) != fast->occluded(segment, stats);
        Hit ours = view->intersect(segment, stats), bvh = fast->intersect(segment, stats);
        disagree += ours.t != bvh.t || ours.prim != bvh.prim;
    }
    CHECK(disagree == 0);

    CHECK_FALSE(fast->queriesAt(bounds.centre()));  // inside the bounds
    CHECK_FALSE(fast->queriesAt(prims.triangle(0)[0]));  // on a triangle
    // Beside the bounds: the scene fills more than a cone of 78 degrees around the light.
    CHECK_FALSE(fast->queriesAt(Vec3(bounds.upper.x + 0.01f * bounds.diagonal().x, bounds.centre().y, bounds.centre().z)));
    // A sphere among the primitives.
    Scene withSphere = scene;
    withSphere.spheres.push_back(Sphere{bounds.centre(), 0.01f, 0});
    PrimitiveSet spherePrims(withSphere);
    CHECK_FALSE(built("fastbvh", spherePrims)->queriesAt(light));
    // The textbook structures make none.
    CHECK_FALSE(built("bvh-buckets", prims)->queriesAt(light));
}

TEST_CASE("point view: a render through it is the textbook BVH's image to the bit") {
    Scene scene = loadFetchedModel("bunny.gltf");
    PrimitiveSet prims(scene);
    auto fast = built("fastbvh", prims);
    auto textbook = built("bvh-buckets", prims);
    const Camera camera = scene.cameras.empty() ? BenchmarkView(scene.bounds()).camera() : scene.cameras.front();
    REQUIRE_FALSE(scene.lights.empty());
    for (const PointLight& light : scene.lights) CHECK(fast->queriesAt(light.position));
    RenderSettings settings;
    settings.width = settings.height = 160;
    settings.threads = 2;
    settings.progress = false;
    RenderResult reference = Renderer(scene, camera, *textbook).render(settings);
    settings.cullOutsideBounds = true;
    RenderResult ours = Renderer(scene, camera, *fast).render(settings);
    REQUIRE(ours.colour.pixels.size() == reference.colour.pixels.size());
    CHECK(std::memcmp(ours.colour.pixels.data(), reference.colour.pixels.data(), ours.colour.pixels.size() * sizeof(float)) == 0);
    CHECK(ours.shadow.rays == reference.shadow.rays);
}
