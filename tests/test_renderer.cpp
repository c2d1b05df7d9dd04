// The renderer against closed forms: Lambert rho/pi, inverse-square point lights, hard
// shadows, emission, smooth normals, lighting from the seen side; and its determinism across
// thread counts. Programmatic scenes, brute-force accelerator over the a0 reference tests.
#include "framework/accel/accelerator.h"
#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/render/renderer.h"
#include "framework/verification/trace_share.h"
#include "framework/scene/icosphere_mesh.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

using namespace rtlab;

namespace {

constexpr double kPi = std::numbers::pi;

uint32_t addMaterial(Scene& scene, Vec3 albedo, Vec3 emission = Vec3(0.0f)) {
    scene.materials.push_back(Material{"", albedo, emission});
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

// An axis-aligned square in the plane z = z0 (two triangles), optionally with vertex normals.
void addSquareZ(Scene& scene, float cx, float cy, float z0, float half, uint32_t material,
                const Vec3* vertexNormal = nullptr) {
    auto base = static_cast<uint32_t>(scene.triangles.positions.size());
    for (Vec3 corner : {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)}) {
        scene.triangles.positions.push_back({cx + half * corner.x, cy + half * corner.y, z0});
        if (vertexNormal) scene.triangles.normals.push_back(*vertexNormal);
    }
    scene.triangles.indices.push_back({base, base + 1, base + 2});
    scene.triangles.indices.push_back({base, base + 2, base + 3});
    for (int k = 0; k < 2; ++k) {
        scene.triangles.material.push_back(material);
        scene.triangles.smooth.push_back(vertexNormal ? 1 : 0);
    }
}

void addLight(Scene& scene, Vec3 position, float intensity) {
    scene.lights.push_back(PointLight{"", position, Vec3(intensity)});
}

// Camera at the origin looking down -Z.
Camera axisCamera(double yfov = 0.9) {
    Camera camera;
    camera.yfov = yfov;
    return camera;
}

RenderResult renderScene(const Scene& scene, const Camera& camera, int width, int height, int threads = 2,
                         std::vector<Aov> aovs = {}, bool cullOutsideBounds = false) {
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator({.name = "brute"});
    accelerator->build(primitives);
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.threads = threads;
    settings.aovs = std::move(aovs);
    settings.progress = false;
    settings.cullOutsideBounds = cullOutsideBounds;
    return Renderer(scene, camera, *accelerator).render(settings);
}

}  // namespace

TEST_CASE("renderer: a square facing a light at the camera gives rho/pi * I * cos / r^2") {
    const float d = 3.0f, intensity = 5.0f, rho = 0.8f;
    Scene scene;
    addSquareZ(scene, 0, 0, -d, 10.0f, addMaterial(scene, Vec3(rho)));
    addLight(scene, {0, 0, 0}, intensity);
    const int size = 33;  // odd: the centre pixel's ray is the optical axis
    RenderResult result = renderScene(scene, axisCamera(), size, size);

    double expectedCentre = rho / kPi * intensity / (d * d);  // 0.8 * 5 / (9 pi)
    for (int c = 0; c < 3; ++c)
        CHECK(result.colour.at(size / 2, size / 2, c) == doctest::Approx(expectedCentre).epsilon(1e-6));

    // Everywhere: the hit is at r = d / |dz| with cos = |dz| (light at the eye), so the
    // radiance is rho/pi * I * |dz|^3 / d^2.
    Camera camera = axisCamera();
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            double dz = std::abs(camera.generateRay(x, y, size, size).direction.z);
            double expected = rho / kPi * intensity * dz * dz * dz / (d * d);
            CHECK(result.colour.at(x, y, 1) == doctest::Approx(expected).epsilon(2e-6));
        }
    }
    CHECK(result.primary.rays == size * size);
    CHECK(result.shadow.rays == size * size);
}

TEST_CASE("renderer: a light behind the surface contributes nothing and casts no shadow ray") {
    Scene scene;
    addSquareZ(scene, 0, 0, -3.0f, 10.0f, addMaterial(scene, Vec3(0.8f)));
    addLight(scene, {0, 0, -6.0f}, 100.0f);
    RenderResult result = renderScene(scene, axisCamera(), 20, 15);
    for (float v : result.colour.pixels) CHECK(v == 0.0f);
    CHECK(result.shadow.rays == 0);
    CHECK(result.primary.rays == 20 * 15);
}

TEST_CASE("renderer: surfaces are lit from the side they are seen from, whatever the winding") {
    Scene front, back;
    addSquareZ(front, 0, 0, -3.0f, 10.0f, addMaterial(front, Vec3(0.5f)));
    addSquareZ(back, 0, 0, -3.0f, 10.0f, addMaterial(back, Vec3(0.5f)));
    for (auto& triangle : back.triangles.indices) std::swap(triangle[1], triangle[2]);  // flipped normal
    addLight(front, {1, 1, 0}, 7.0f);
    addLight(back, {1, 1, 0}, 7.0f);
    RenderResult a = renderScene(front, axisCamera(), 16, 16);
    RenderResult b = renderScene(back, axisCamera(), 16, 16);
    // Equal up to rounding: the flipped winding reorders the barycentric point reconstruction.
    REQUIRE(a.colour.pixels.size() == b.colour.pixels.size());
    for (size_t i = 0; i < a.colour.pixels.size(); ++i)
        CHECK(b.colour.pixels[i] == doctest::Approx(a.colour.pixels[i]).epsilon(1e-6));
    CHECK(a.colour.at(8, 8, 0) > 0.0f);
}

TEST_CASE("renderer: an occluder casts a hard shadow; lit points follow the closed form") {
    const float rho = 0.6f, intensity = 2.0f;
    Scene scene;
    uint32_t grey = addMaterial(scene, Vec3(rho));
    addSquareZ(scene, 0, 0, -3.0f, 10.0f, grey);   // prims 0, 1: the wall
    addSquareZ(scene, 1, 0, -2.0f, 0.2f, grey);    // prims 2, 3: the occluder
    const Vec3 light(1.0f, 0.0f, -1.0f);
    addLight(scene, light, intensity);
    // Seen from the light, the occluder (half size 0.2 at distance 1) shadows the square of
    // half size 0.4 around (1, 0, -3) on the wall.
    const int width = 96, height = 64;
    Camera camera = axisCamera();
    RenderResult result = renderScene(scene, camera, width, height, 2, {Aov::Primitive, Aov::Depth});

    int shadowed = 0, lit = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            uint32_t prim = result.aovs.primitive[static_cast<size_t>(y) * width + x];
            if (prim > 1) continue;  // the occluder itself
            Ray ray = camera.generateRay(x, y, width, height);
            DVec3 p = DVec3(ray.direction) * (3.0 / -static_cast<double>(ray.direction.z));
            CHECK(result.aovs.depth.at(x, y, 0) == doctest::Approx(glm::length(p)).epsilon(1e-6));
            double edge = std::max(std::abs(p.x - 1.0), std::abs(p.y));  // distance in the max norm
            if (edge < 0.39) {
                ++shadowed;
                CHECK(result.colour.at(x, y, 0) == 0.0f);
            } else if (edge > 0.41) {
                ++lit;
                DVec3 toLight = DVec3(light) - p;
                double r = glm::length(toLight);
                double expected = rho / kPi * intensity * (toLight.z / r) / (r * r);
                CHECK(result.colour.at(x, y, 0) == doctest::Approx(expected).epsilon(2e-6));
            }
        }
    }
    CHECK(shadowed > 50);  // the test really looked at the shadow
    CHECK(lit > 1000);
}

TEST_CASE("renderer: no self-shadowing on a large floor at y = 0 (shadow rays start on the plane)") {
    // Vertices at +-4 and y = 0 exactly: the hit points have no error in y, so shadow rays
    // start exactly on the floor, where a float triangle test re-hits it at t ~ 1e-8.
    const float rho = 0.7f, intensity = 30.0f;
    Scene scene;
    uint32_t material = addMaterial(scene, Vec3(rho));
    scene.triangles.positions = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}};
    scene.triangles.indices = {{0, 1, 2}, {0, 2, 3}};
    scene.triangles.material = {material, material};
    scene.triangles.smooth = {0, 0};
    const Vec3 light(2.0f, 4.0f, 3.0f);
    addLight(scene, light, intensity);
    Camera camera;
    camera.position = {0.0, 1.75, 5.5};
    camera.forward = {0.0, -0.5, -1.0};
    const int width = 80, height = 60;
    RenderResult result = renderScene(scene, camera, width, height);
    int floorPixels = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            DVec3 direction(camera.generateRay(x, y, width, height).direction);
            DVec3 p = camera.position + direction * (-camera.position.y / direction.y);
            if (direction.y >= 0.0 || std::abs(p.x) > 3.99 || std::abs(p.z) > 3.99) continue;
            ++floorPixels;
            DVec3 toLight = DVec3(light) - p;
            double r = glm::length(toLight);
            double expected = rho / kPi * intensity * (toLight.y / r) / (r * r);
            CHECK(result.colour.at(x, y, 0) == doctest::Approx(expected).epsilon(2e-6));
        }
    }
    CHECK(floorPixels > 2000);
}

TEST_CASE("renderer: emission adds to reflected light; no lights means no shadow rays") {
    Scene plain;
    addSquareZ(plain, 0, 0, -2.0f, 10.0f, addMaterial(plain, Vec3(0.5f)));
    RenderResult unlit = renderScene(plain, axisCamera(), 9, 9);
    CHECK(unlit.colour.rgb(4, 4) == Vec3(0.0f));
    CHECK(unlit.shadow.rays == 0);

    // An emissive square is an area light, but a flat light does not light itself (cos = 0).
    const Vec3 emission(0.1f, 0.2f, 0.3f);
    Scene scene;
    addSquareZ(scene, 0, 0, -2.0f, 10.0f, addMaterial(scene, Vec3(0.5f), emission));
    RenderResult dark = renderScene(scene, axisCamera(), 9, 9);
    for (int c = 0; c < 3; ++c) {
        CHECK(dark.colour.at(4, 4, c) == doctest::Approx(emission[c]).epsilon(1e-6));
        CHECK(dark.colour.at(0, 0, c) == doctest::Approx(emission[c]).epsilon(1e-6));
    }

    addLight(scene, {0, 0, 0}, 3.0f);
    RenderResult lit = renderScene(scene, axisCamera(), 9, 9);
    double reflected = 0.5 / kPi * 3.0 / 4.0;
    for (int c = 0; c < 3; ++c)
        CHECK(lit.colour.at(4, 4, c) == doctest::Approx(emission[c] + reflected).epsilon(1e-6));
}

TEST_CASE("renderer: smooth triangles shade with the interpolated normal; misses are black") {
    const Vec3 tilted = glm::normalize(Vec3(1.0f, 0.0f, 1.0f));
    Scene scene;
    addSquareZ(scene, 0, 0, -2.0f, 1.0f, addMaterial(scene, Vec3(1.0f)), &tilted);
    addLight(scene, {0, 0, 0}, 4.0f);
    RenderResult result = renderScene(scene, axisCamera(1.5), 31, 31, 2, {Aov::Normal});
    // At the centre the light is straight ahead: cos = dot(tilted, +z) = 1/sqrt(2).
    double expected = 1.0 / kPi * 4.0 * std::sqrt(0.5) / 4.0;
    CHECK(result.colour.at(15, 15, 0) == doctest::Approx(expected).epsilon(1e-6));
    CHECK(result.aovs.normal.rgb(15, 15).x == doctest::Approx(0.5 + 0.5 * std::sqrt(0.5)).epsilon(1e-6));
    // The square covers half a unit of tan(fov) at distance 2; the corners miss.
    CHECK(result.colour.rgb(0, 0) == Vec3(0.0f));
    CHECK(result.aovs.normal.rgb(0, 0) == Vec3(0.0f));
}

TEST_CASE("renderer: a sphere facing a light at the camera") {
    Scene scene;
    scene.spheres.push_back(Sphere{{0, 0, -5}, 1.5f, addMaterial(scene, Vec3(0.9f))});
    addLight(scene, {0, 0, 0}, 10.0f);
    RenderResult result = renderScene(scene, axisCamera(), 21, 21);
    CHECK(result.colour.at(10, 10, 2) == doctest::Approx(0.9 / kPi * 10.0 / (3.5 * 3.5)).epsilon(1e-6));
}

TEST_CASE("renderer: 1, 2 and 7 threads give bit-identical images, AOVs and statistics") {
    Scene scene;
    Pcg32 random(42, 3);
    auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * random.uniform(); };
    for (int m = 0; m < 4; ++m)
        addMaterial(scene, {uniform(0, 1), uniform(0, 1), uniform(0, 1)}, Vec3(m == 3 ? 0.05f : 0.0f));
    for (int t = 0; t < 150; ++t) {
        Vec3 centre(uniform(-3, 3), uniform(-2, 2), uniform(-9, -4));
        auto base = static_cast<uint32_t>(scene.triangles.positions.size());
        for (int v = 0; v < 3; ++v)
            scene.triangles.positions.push_back(centre + Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
        scene.triangles.indices.push_back({base, base + 1, base + 2});
        scene.triangles.material.push_back(static_cast<uint32_t>(t % 4));
        scene.triangles.smooth.push_back(0);
    }
    for (int s = 0; s < 6; ++s)
        scene.spheres.push_back(Sphere{{uniform(-3, 3), uniform(-2, 2), uniform(-9, -4)}, uniform(0.2f, 0.8f),
                                       static_cast<uint32_t>(s % 4)});
    addLight(scene, {2, 3, 0}, 30.0f);
    addLight(scene, {-3, -1, -2}, 8.0f);
    Camera camera = axisCamera();
    std::vector<Aov> all{Aov::Normal, Aov::Depth, Aov::Primitive, Aov::Cost};
    // 61 x 47 is not a multiple of the tile size: edge tiles are clipped.
    RenderResult one = renderScene(scene, camera, 61, 47, 1, all);
    double lit = 0.0;
    for (float v : one.colour.pixels) lit += v;
    CHECK(lit > 0.0);
    CHECK(one.shadow.rays > 0);
    for (int threads : {2, 7}) {
        CAPTURE(threads);
        RenderResult other = renderScene(scene, camera, 61, 47, threads, all);
        REQUIRE(other.colour.pixels.size() == one.colour.pixels.size());
        CHECK(std::memcmp(other.colour.pixels.data(), one.colour.pixels.data(),
                          one.colour.pixels.size() * sizeof(float)) == 0);
        CHECK(std::memcmp(other.aovs.depth.pixels.data(), one.aovs.depth.pixels.data(),
                          one.aovs.depth.pixels.size() * sizeof(float)) == 0);
        CHECK(other.aovs.normal.pixels == one.aovs.normal.pixels);
        CHECK(other.aovs.primitive == one.aovs.primitive);
        CHECK(other.aovs.cost == one.aovs.cost);
        CHECK(other.primary.nodeVisits == one.primary.nodeVisits);
        CHECK(other.primary.primitiveTests == one.primary.primitiveTests);
        CHECK(other.shadow.rays == one.shadow.rays);
        CHECK(other.shadow.primitiveTests == one.shadow.primitiveTests);
    }
}

TEST_CASE("renderer: image sizes out of range are errors") {
    Scene scene;
    addSquareZ(scene, 0, 0, -3.0f, 1.0f, addMaterial(scene, Vec3(0.5f)));
    CHECK_THROWS_AS(renderScene(scene, axisCamera(), 0, 10), Error);
    CHECK_THROWS_AS(renderScene(scene, axisCamera(), 10, -1), Error);
}

TEST_CASE("renderer: AOV images (depth scaled for integer files, cost and steps ramps, primitive colours)") {
    Scene scene;
    addSquareZ(scene, 0, 0, -3.0f, 1.0f, addMaterial(scene, Vec3(0.5f)));  // leaves the corners empty
    const int size = 24;
    RenderResult result = renderScene(scene, axisCamera(), size, size, 2, {Aov::Depth, Aov::Primitive, Aov::Cost, Aov::Steps});
    const AovBuffers& aovs = result.aovs;
    CHECK(aovs.depth.at(0, 0, 0) == kInfinity);  // a miss
    CHECK(aovs.primitive[0] == kNoHit);

    Image depthFloat = aovImage(Aov::Depth, aovs, size, size, false);
    Image depthInteger = aovImage(Aov::Depth, aovs, size, size, true);
    CHECK(depthFloat.pixels == aovs.depth.pixels);
    CHECK(depthInteger.at(0, 0, 0) == 0.0f);
    float largest = *std::max_element(depthInteger.pixels.begin(), depthInteger.pixels.end());
    CHECK(largest == 1.0f);

    // Brute force tests both triangles for every ray: the cost is 2 everywhere, the ramp's top;
    // it has no structure, so no steps at all.
    CHECK(maxCount(aovs.cost) == 2);
    Image cost = aovImage(Aov::Cost, aovs, size, size, true);
    CHECK(cost.rgb(0, 0) == heatColour(1.0f));
    CHECK(maxCount(aovs.steps) == 0);
    CHECK(aovImage(Aov::Steps, aovs, size, size, true).rgb(0, 0) == heatColour(0.0f));
    CHECK(heatColour(0.0f) != heatColour(1.0f));

    Image prim = aovImage(Aov::Primitive, aovs, size, size, true);
    CHECK(prim.rgb(0, 0) == Vec3(0.0f));
    CHECK(prim.rgb(size / 2 + 1, size / 2 - 1) == primitiveColour(aovs.primitive[(size / 2 - 1) * size + size / 2 + 1]));
    CHECK(primitiveColour(0) != primitiveColour(1));
    CHECK(parseAov("prim") == Aov::Primitive);
    CHECK_THROWS_AS(parseAov("albedo"), Error);
}

TEST_CASE("renderer: the trace share replays exactly the render's own accelerator queries") {
    Scene scene;
    uint32_t grey = addMaterial(scene, Vec3(0.6f));
    addSquareZ(scene, 0, 0, -3.0f, 10.0f, grey);
    addSquareZ(scene, 1, 0, -2.0f, 0.2f, grey);
    addLight(scene, {1.0f, 0.0f, -1.0f}, 2.0f);
    addLight(scene, {-1.0f, 0.5f, -1.0f}, 1.0f);
    RenderResult render = renderScene(scene, axisCamera(), 48, 32);
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator({.name = "brute"});
    accelerator->build(primitives);
    RenderSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.threads = 2;
    TraceShare share = measureTraceShare(scene, axisCamera(), *accelerator, settings, 2);
    // Every camera ray and every shadow ray, once.
    CHECK(share.queries == render.primary.rays + render.shadow.rays);
    CHECK(render.shadow.rays > 0);
    CHECK(share.renderSeconds > 0.0);
    CHECK(share.traceSeconds > 0.0);
    CHECK(share.beyondTracing() >= 0.0);
    CHECK(share.beyondTracing() < 1.0);
    CHECK(TraceShare{2.0, 1.5, 1, {}}.beyondTracing() == doctest::Approx(0.25));
    CHECK(TraceShare{1.0, 1.5, 1, {}}.beyondTracing() == 0.0);  // a replay slower than the render: none beyond
    // One share per pass, and their median.
    CHECK(share.passShares.size() == 2);
    CHECK(TraceShare{1.0, 0.5, 1, {0.3, 0.1, 0.2}}.pairedBeyondTracing() == doctest::Approx(0.2));
    CHECK(TraceShare{1.0, 0.5, 1, {0.4, 0.1, 0.2, 0.3}}.pairedBeyondTracing() == doctest::Approx(0.25));
    CHECK(TraceShare{2.0, 1.5, 1, {}}.pairedBeyondTracing() == doctest::Approx(0.25));  // no passes: the best against the best
}

TEST_CASE("renderer: the centre-ray path gives the general path's colours, bit for bit") {
    // A render asking for an AOV takes the general path (sample loop, AOVs); without, one ray
    // per pixel centre and point lights take renderCentres (an emitter would be an area light:
    // the general path). The colours must not differ: a smooth-shaded square, a square casting
    // a shadow on it, two lights.
    Scene scene;
    uint32_t grey = addMaterial(scene, Vec3(0.6f));
    const Vec3 tilted = glm::normalize(Vec3(0.3f, 0.1f, 1.0f));
    addSquareZ(scene, 0, 0, -3.0f, 10.0f, grey, &tilted);
    addSquareZ(scene, 1, 0, -2.0f, 0.2f, addMaterial(scene, Vec3(0.2f, 0.7f, 0.4f)));
    addLight(scene, {1.0f, 0.0f, -1.0f}, 2.0f);
    addLight(scene, {-1.0f, 0.5f, -1.0f}, 1.0f);
    RenderResult plain = renderScene(scene, axisCamera(), 48, 32);
    RenderResult general = renderScene(scene, axisCamera(), 48, 32, 2, {Aov::Depth});
    REQUIRE(plain.colour.pixels.size() == general.colour.pixels.size());
    CHECK(std::memcmp(plain.colour.pixels.data(), general.colour.pixels.data(), plain.colour.pixels.size() * sizeof(float)) == 0);
    CHECK(plain.shadow.rays == general.shadow.rays);
}

namespace {

// Every shadow ray a render asks its accelerator about, as the bits of its origin, direction
// and interval, in sorted order (the batched path asks in another order).
class ShadowRayRecorder : public Accelerator {
public:
    explicit ShadowRayRecorder(const Accelerator& inner) : inner_(inner) {}
    void build(const PrimitiveSet&) override {}
    Hit intersect(const Ray& ray, TraversalStats& stats) const override { return inner_.intersect(ray, stats); }
    bool occluded(const Ray& ray, TraversalStats& stats) const override {
        std::array<float, 8> values{ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x,
                                    ray.direction.y, ray.direction.z, ray.tMin, ray.tMax};
        std::array<uint32_t, 8> bits;
        std::memcpy(bits.data(), values.data(), sizeof bits);
        rays_.push_back(bits);
        return inner_.occluded(ray, stats);
    }
    StructureView structure() const override { return inner_.structure(); }
    size_t memoryBytes() const override { return 0; }

    std::vector<std::array<uint32_t, 8>> sortedRays() const {
        auto sorted = rays_;
        std::sort(sorted.begin(), sorted.end());
        return sorted;
    }

private:
    const Accelerator& inner_;
    mutable std::vector<std::array<uint32_t, 8>> rays_;
};

std::vector<std::array<uint32_t, 8>> shadowRaysOf(const Scene& scene, int width, int height, std::vector<Aov> aovs) {
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator({.name = "brute"});
    accelerator->build(primitives);
    ShadowRayRecorder recorder(*accelerator);
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.threads = 1;
    settings.aovs = std::move(aovs);
    settings.progress = false;
    Renderer(scene, axisCamera(), recorder).render(settings);
    return recorder.sortedRays();
}

}  // namespace

TEST_CASE("renderer: the batched shading of the centre-ray path is directLighting's, bit for bit, on every kind of hit") {
    // PointLightBatch shades a smooth mesh whose normals vary from vertex to vertex, flat floor
    // triangles (whole rows of hits: batches that fill up), a tilted flat triangle and a
    // degenerate one; it hands
    // spheres and black surfaces back to directLighting. Three lights, one of them behind the
    // floor; an image whose size is no multiple of the tile size.
    Scene scene;
    const uint32_t grey = addMaterial(scene, Vec3(0.6f, 0.5f, 0.4f));
    IndexedMesh ball = icosphereMesh(2);
    const auto base = static_cast<uint32_t>(scene.triangles.positions.size());
    for (const Vec3& p : ball.positions) {
        scene.triangles.positions.push_back(Vec3(0.0f, 0.0f, -4.0f) + 0.9f * p);
        scene.triangles.normals.push_back(p);
    }
    for (const auto& t : ball.triangles) {
        scene.triangles.indices.push_back({base + t[0], base + t[1], base + t[2]});
        scene.triangles.material.push_back(grey);
        scene.triangles.smooth.push_back(1);
    }
    addSquareZ(scene, 0, 0, -6.0f, 8.0f, addMaterial(scene, Vec3(0.3f, 0.7f, 0.5f)));
    addSquareZ(scene, -1.2f, 0.8f, -3.5f, 0.3f, addMaterial(scene, Vec3(0.0f)));  // black
    auto addFlatTriangle = [&](std::array<Vec3, 3> corners) {
        const auto first = static_cast<uint32_t>(scene.triangles.positions.size());
        for (const Vec3& c : corners) scene.triangles.positions.push_back(c);
        scene.triangles.indices.push_back({first, first + 1, first + 2});
        scene.triangles.material.push_back(grey);
        scene.triangles.smooth.push_back(0);
    };
    addFlatTriangle({Vec3(-1.5f, -1.0f, -3.2f), Vec3(-0.5f, -1.2f, -3.6f), Vec3(-1.0f, -0.3f, -3.3f)});  // tilted
    addFlatTriangle({Vec3(0.5f, -0.5f, -3.0f), Vec3(0.5f, -0.5f, -3.0f), Vec3(0.7f, -0.2f, -3.0f)});    // degenerate
    scene.spheres.push_back(Sphere{{1.3f, -0.7f, -3.5f}, 0.4f, grey});
    addLight(scene, {1.0f, 1.5f, -1.0f}, 3.0f);
    addLight(scene, {-2.0f, -1.0f, -2.0f}, 1.5f);
    addLight(scene, {0.0f, 0.0f, -9.0f}, 5.0f);  // behind the floor
    RenderResult plain = renderScene(scene, axisCamera(), 53, 37);
    RenderResult general = renderScene(scene, axisCamera(), 53, 37, 2, {Aov::Depth});
    REQUIRE(plain.colour.pixels.size() == general.colour.pixels.size());
    CHECK(std::memcmp(plain.colour.pixels.data(), general.colour.pixels.data(), plain.colour.pixels.size() * sizeof(float)) == 0);
    CHECK(plain.shadow.rays == general.shadow.rays);
    CHECK(plain.shadow.primitiveTests == general.shadow.primitiveTests);
    CHECK(plain.primary.rays == general.primary.rays);
    CHECK(plain.culledRays == 0);
    // Skipping the rows that cannot reach the scene's bounds changes nothing but the rays asked.
    // A wider view, so that the floor leaves rows and tiles beside it.
    RenderResult wide = renderScene(scene, axisCamera(2.6), 53, 37, 2, {Aov::Depth});
    RenderResult culled = renderScene(scene, axisCamera(2.6), 53, 37, 2, {}, true);
    CHECK(std::memcmp(culled.colour.pixels.data(), wide.colour.pixels.data(), wide.colour.pixels.size() * sizeof(float)) == 0);
    CHECK(culled.culledRays > 0);
    CHECK(culled.primary.rays + culled.culledRays == wide.primary.rays);
    CHECK(culled.shadow.rays == wide.shadow.rays);
    // The same shadow rays, to the bit: their origins moved off the surface the same way.
    CHECK(shadowRaysOf(scene, 53, 37, {}) == shadowRaysOf(scene, 53, 37, {Aov::Depth}));
}
