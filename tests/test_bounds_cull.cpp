// BoundsCull (framework/render/bounds_cull.h): a tile row it skips holds no camera ray that
// reaches the scene's bounds by a0's slab test, on random cameras and on bounds that touch a
// pixel centre's ray; and it does skip.
#include "framework/core/pcg32.h"
#include "framework/interface/a0_intersect.h"
#include "framework/render/bounds_cull.h"
#include "framework/render/tiles.h"
#include "framework/scene/camera.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

using namespace rtlab;

namespace {

constexpr int kWidth = 64, kHeight = 48;

Vec3 randomPoint(Pcg32& rng, float scale) {
    return scale * Vec3(2.0f * rng.uniform() - 1.0f, 2.0f * rng.uniform() - 1.0f, 2.0f * rng.uniform() - 1.0f);
}

Camera randomCamera(Pcg32& rng) {
    Camera camera;
    camera.position = DVec3(randomPoint(rng, 10.0f));
    camera.forward = DVec3(randomPoint(rng, 1.0f)) + DVec3(0.0, 0.0, -0.01);
    camera.up = DVec3(randomPoint(rng, 1.0f)) + DVec3(0.01, 0.0, 0.0);
    camera.yfov = 0.2 + 1.2 * rng.uniform();
    return camera;
}

bool reaches(const Ray& ray, const Bounds3f& box) {
    float tEnter = 0.0f;
    return intersectBox(box, RayInverse(ray), 0.0f, kInfinity, &tEnter);
}

struct Tally {
    int skipped = 0, traced = 0;
};

// Every tile row the cull skips: none of its rays reaches the box.
Tally checkImage(const Camera& camera, const Bounds3f& box) {
    CameraFilm film = camera.film(kWidth, kHeight);
    BoundsCull cull(film, std::span(&box, 1));
    Tally tally;
    for (const Tile& tile : makeTiles(kWidth, kHeight)) {
        for (int y = tile.y0; y < tile.y1; ++y) {
            if (!cull.row(y).misses(tile.x0, tile.x1)) {
                ++tally.traced;
                continue;
            }
            ++tally.skipped;
            for (int x = tile.x0; x < tile.x1; ++x) {
                Ray ray = film.through(x + 0.5, y + 0.5);
                INFO("pixel " << x << ", " << y);
                REQUIRE_FALSE(reaches(ray, box));
            }
        }
    }
    return tally;
}

}  // namespace

TEST_CASE("bounds cull: a skipped row's rays miss random bounds, and most rows away from them are skipped") {
    Pcg32 rng(7, 1);
    Tally total;
    for (int scene = 0; scene < 300; ++scene) {
        Camera camera = randomCamera(rng);
        Vec3 centre = randomPoint(rng, 10.0f);
        Bounds3f box(centre - Vec3(rng.uniform() * 3.0f), centre + Vec3(rng.uniform() * 3.0f));
        Tally tally = checkImage(camera, box);
        total.skipped += tally.skipped;
        total.traced += tally.traced;
    }
    // Random boxes fill a small part of most images: a cull that never skipped would fail here.
    CHECK(total.skipped > 2 * total.traced);
}

TEST_CASE("bounds cull: bounds that a pixel centre's ray touches keep that ray's row") {
    Pcg32 rng(11, 3);
    for (int scene = 0; scene < 300; ++scene) {
        Camera camera = randomCamera(rng);
        CameraFilm film = camera.film(kWidth, kHeight);
        int x = int(rng.uniform() * kWidth), y = int(rng.uniform() * kHeight);
        Ray ray = film.through(x + 0.5, y + 0.5);
        // A corner, an edge or a face of the box on the ray, the box on any side of it.
        Vec3 onRay = ray.at(0.5f + 20.0f * rng.uniform());
        Vec3 extent(rng.uniform() * 2.0f, rng.uniform() * 2.0f, rng.uniform() * 2.0f);
        for (int axis = 0; axis < 3; ++axis)
            if (rng.uniform() < 0.3f) extent[axis] = 0.0f;  // flat: the ray grazes a face
        Vec3 away(rng.uniform() < 0.5f ? 1.0f : -1.0f, rng.uniform() < 0.5f ? 1.0f : -1.0f, rng.uniform() < 0.5f ? 1.0f : -1.0f);
        Bounds3f box(onRay, onRay + away * extent);
        if (!reaches(ray, box)) continue;  // a0's test is the judge; it may round the other way
        BoundsCull cull(film, std::span(&box, 1));
        int x0 = x / kTileSize * kTileSize;
        INFO("scene " << scene << ", pixel " << x << ", " << y);
        CHECK_FALSE(cull.row(y).misses(x0, std::min(x0 + kTileSize, kWidth)));
        CHECK_FALSE(cull.row(y).misses(x, x + 1));
        checkImage(camera, box);
    }
}

TEST_CASE("bounds cull: a camera inside the bounds or bounds not finite skip nothing; empty bounds skip everything") {
    Camera camera;  // at the origin, looking down -Z
    CameraFilm film = camera.film(kWidth, kHeight);
    auto misses = [&film](std::vector<Bounds3f> boxes, int y) { return BoundsCull(film, boxes).row(y).misses(0, kWidth); };
    const Bounds3f around(Vec3(-1.0f, -1.0f, 0.0f), Vec3(1.0f, 1.0f, 2.0f));  // behind the film, around the eye
    const Bounds3f notFinite(Vec3(-kInfinity, 5.0f, -3.0f), Vec3(-4.0f, 6.0f, -2.0f));
    const Bounds3f left(Vec3(-40.0f, -1.0f, -6.0f), Vec3(-30.0f, 1.0f, -4.0f));  // in front, well to the left
    const Bounds3f ahead(Vec3(-1.0f, -1.0f, -6.0f), Vec3(1.0f, 1.0f, -4.0f));
    for (int y = 0; y < kHeight; ++y) {
        CHECK_FALSE(misses({around}, y));
        CHECK_FALSE(misses({left, around}, y));
        CHECK_FALSE(misses({notFinite}, y));
        CHECK(misses({Bounds3f{}}, y));
        CHECK(misses({}, y));
        CHECK(misses({left}, y));
    }
    CHECK_FALSE(misses({ahead}, kHeight / 2));
    CHECK_FALSE(misses({left, ahead}, kHeight / 2));
}

TEST_CASE("bounds cull: two boxes leave the rows between them, which their common box would keep") {
    Camera camera;  // at the origin, looking down -Z
    CameraFilm film = camera.film(kWidth, kHeight);
    const Bounds3f top(Vec3(-1.0f, 2.0f, -6.0f), Vec3(1.0f, 3.0f, -5.0f)), bottom(Vec3(-1.0f, -3.0f, -6.0f), Vec3(1.0f, -2.0f, -5.0f));
    Bounds3f both = top;
    both.extend(bottom);
    std::vector<Bounds3f> pair{top, bottom};
    CHECK(BoundsCull(film, pair).row(kHeight / 2).misses(0, kWidth));
    CHECK_FALSE(BoundsCull(film, std::span(&both, 1)).row(kHeight / 2).misses(0, kWidth));
}

TEST_CASE("bounds cull: the scene's boxes hold every primitive and nothing beyond the scene's bounds") {
    Scene scene;
    Pcg32 rng(5, 9);
    for (int i = 0; i < 200; ++i) {
        Vec3 p = randomPoint(rng, 4.0f);
        auto first = static_cast<uint32_t>(scene.triangles.positions.size());
        for (int v = 0; v < 3; ++v) scene.triangles.positions.push_back(p + randomPoint(rng, 0.5f));
        scene.triangles.indices.push_back({first, first + 1, first + 2});
        scene.triangles.material.push_back(0);
        scene.triangles.smooth.push_back(0);
    }
    scene.spheres.push_back(Sphere{{5.0f, 5.0f, 5.0f}, 1.0f, 0});
    std::vector<Bounds3f> boxes = sceneBoxes(scene);
    CHECK(boxes.size() == 8);
    Bounds3f all;
    for (const Bounds3f& box : boxes) all.extend(box);
    CHECK(all.lower == scene.bounds().lower);
    CHECK(all.upper == scene.bounds().upper);
    for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim) {
        Bounds3f b = scene.primitiveBounds(prim);
        CHECK(std::any_of(boxes.begin(), boxes.end(), [&b](const Bounds3f& box) {
            return glm::all(glm::lessThanEqual(box.lower, b.lower)) && glm::all(glm::lessThanEqual(b.upper, box.upper));
        }));
    }
    CHECK(sceneBoxes(Scene{}).empty());
}
