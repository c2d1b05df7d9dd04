// The renderer with area and sphere lights (docs/rendering.md#area-and-sphere-lights): each way
// of sampling them (--light-sampling) against closed forms of the irradiance, emission seen from
// the front only, and bit-identical images for any thread count at any samples per pixel.
// Reference solutions of a6 and a0, brute-force accelerator.
#include "framework/accel/accelerator.h"
#include "framework/core/error.h"
#include "framework/oracle/closed_forms.h"
#include "framework/render/renderer.h"
#include "framework/scene/emitters.h"
#include "framework/scene/gltf_loader.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>
#include <optional>

using namespace rtlab;

namespace {

constexpr double kPi = std::numbers::pi;

std::string sceneFile(const std::string& name) { return std::string(RTLAB_SOURCE_DIR) + "/scenes/" + name; }

uint32_t addMaterial(Scene& scene, Vec3 albedo, Vec3 emission = Vec3(0.0f), bool doubleSided = false) {
    scene.materials.push_back(Material{"", albedo, emission, doubleSided});
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

// The parallelogram corner, corner + u, corner + u + v, corner + v; its front faces u x v.
void addQuad(Scene& scene, Vec3 corner, Vec3 u, Vec3 v, uint32_t material) {
    auto base = static_cast<uint32_t>(scene.triangles.positions.size());
    for (Vec3 p : {corner, corner + u, corner + u + v, corner + v}) scene.triangles.positions.push_back(p);
    scene.triangles.indices.push_back({base, base + 1, base + 2});
    scene.triangles.indices.push_back({base, base + 2, base + 3});
    for (int k = 0; k < 2; ++k) {
        scene.triangles.material.push_back(material);
        scene.triangles.smooth.push_back(0);
    }
}

Camera lookAt(DVec3 position, DVec3 target, double yfov) {
    Camera camera;
    camera.position = position;
    camera.forward = glm::normalize(target - position);
    camera.yfov = yfov;
    return camera;
}

struct Render {
    int width = 48, height = 36, spp = 1, threads = 2;
    uint64_t seed = 0;
    LightSampling sampling = LightSampling::SolidAngle;
};

RenderResult render(const Scene& scene, const Camera& camera, const Render& r) {
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator({.name = "brute"});
    accelerator->build(primitives);
    RenderSettings settings;
    settings.width = r.width;
    settings.height = r.height;
    settings.threads = r.threads;
    settings.progress = false;
    settings.samplesPerPixel = r.spp;
    settings.seed = r.seed;
    settings.lightSampling = r.sampling;
    return Renderer(scene, camera, *accelerator).render(settings);
}

// The expected value of each pixel: the radiance at the ground (y = 0) point each of 8 x 8 film
// positions sees, averaged; nullopt where a position misses the ground (|x|, |z| <= half).
using GroundRadiance = std::function<double(const DVec3& point)>;

std::vector<std::optional<double>> expectedPixels(const Camera& camera, int width, int height, double half,
                                                  const GroundRadiance& radiance) {
    std::vector<std::optional<double>> expected(static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            bool ground = true;
            for (int k = 0; k < 64 && ground; ++k) {
                Ray ray = camera.generateRayThrough(x + (k % 8 + 0.5) / 8, y + (k / 8 + 0.5) / 8, width, height);
                double t = -double(ray.origin.y) / ray.direction.y;
                DVec3 p = DVec3(ray.origin) + t * DVec3(ray.direction);
                ground = t > 0.0 && std::abs(p.x) <= half && std::abs(p.z) <= half;
                if (ground) sum += radiance(p);
            }
            if (ground) expected[static_cast<size_t>(y) * width + x] = sum / 64.0;
        }
    return expected;
}

// The pixels' residuals against the closed form: their mean, its standard error (pixels are
// independent: each has its own random stream) and the mean expected value.
struct Residuals {
    size_t pixels = 0;
    double mean = 0.0, standardError = 0.0, expectedMean = 0.0;
    double z() const { return mean / standardError; }
};

Residuals residuals(const Image& image, const std::vector<std::optional<double>>& expected) {
    Residuals r;
    double sum = 0.0, sumSquares = 0.0, expectedSum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const auto& e = expected[static_cast<size_t>(y) * image.width + x];
            if (!e) continue;
            double d = image.at(x, y, 1) - *e;
            sum += d;
            sumSquares += d * d;
            expectedSum += *e;
            ++r.pixels;
        }
    double n = static_cast<double>(r.pixels);
    r.mean = sum / n;
    r.standardError = std::sqrt((sumSquares / n - r.mean * r.mean) / (n - 1.0));
    r.expectedMean = expectedSum / n;
    return r;
}

// Unbiased within the noise: |z| below the two-sided point of level 1 - 0.99^(1/4) of the normal
// distribution (alpha = 0.01 with Sidak's correction over the four light samplings a test case
// checks), and a standard error below 0.5 % of the mean, so that a bias of 1.6 % or more cannot
// pass.
constexpr double kCriticalZ = 3.022;

void checkUnbiased(const Residuals& r) {
    CAPTURE(r.z());
    CAPTURE(r.pixels);
    CAPTURE(r.mean);
    CAPTURE(r.standardError);
    CAPTURE(r.expectedMean);
    REQUIRE(r.pixels > 500);
    CHECK(std::abs(r.z()) < kCriticalZ);
    CHECK(r.standardError < 0.005 * r.expectedMean);
}

// Samples per pixel that bring each estimator's standard error on these scenes below 0.5 %:
// directions about the normal find a small light rarely.
int samplesFor(LightSampling sampling) {
    return sampling == LightSampling::Area || sampling == LightSampling::SolidAngle ? 64 : 1024;
}

// A 48 x 36 render of the ground (|x|, |z| <= 10 at y = 0) with each light sampling, unbiased
// against `exact`.
void checkEveryLightSampling(const Scene& scene, const Camera& camera, const GroundRadiance& exact, uint64_t seed) {
    auto expected = expectedPixels(camera, 48, 36, 10.0, exact);
    for (LightSampling sampling : kLightSamplings) {
        CAPTURE(std::string(lightSamplingName(sampling)));
        RenderResult result = render(scene, camera, {.spp = samplesFor(sampling), .seed = seed, .sampling = sampling});
        checkUnbiased(residuals(result.colour, expected));
    }
}

}  // namespace

TEST_CASE("area lights: scenes/radiometry/closed-form.gltf against Lambert's contour formula, every light sampling") {
    Scene scene = loadGltf(sceneFile("radiometry/closed-form.gltf"));
    std::vector<std::array<DVec3, 3>> light;
    for (const Emitter& e : findEmitters(scene)) {
        auto v = scene.triangleVertices(e.prim);
        light.push_back({DVec3(v[0]), DVec3(v[1]), DVec3(v[2])});
    }
    REQUIRE(light.size() == 2);
    const double radiance = 4.0, albedo = 0.8;  // scripts/make-scenes.py, closed_form()
    // Under the centre of the unit square at height 1: 0.752274688454 L (four corner form factors).
    CHECK(polygonIrradiance({0, 0, 0}, {0, 1, 0}, light[0]) + polygonIrradiance({0, 0, 0}, {0, 1, 0}, light[1]) ==
          doctest::Approx(0.752274688454).epsilon(1e-10));
    GroundRadiance exact = [&](const DVec3& p) {
        double e = 0.0;
        for (const auto& triangle : light) e += polygonIrradiance(p, {0, 1, 0}, triangle);
        return albedo / kPi * radiance * e;
    };
    checkEveryLightSampling(scene, scene.cameras.front(), exact, 7);
}

TEST_CASE("area lights: a sphere light over a plane against pi L sin^2(alpha) cos(theta), every light sampling") {
    Scene scene;
    addQuad(scene, {-10, 0, 10}, {20, 0, 0}, {0, 0, -20}, addMaterial(scene, Vec3(0.7f)));  // facing up
    const float radius = 0.3f, radiance = 5.0f;
    const DVec3 centre(0.2, 1.2, -0.3);
    scene.spheres.push_back(Sphere{Vec3(centre), radius, addMaterial(scene, Vec3(0.0f), Vec3(radiance))});
    Camera camera = lookAt({0, 0.6, 3}, {0, 0, 0}, 0.5);  // the sphere stays above the picture
    GroundRadiance exact = [&](const DVec3& p) {
        return 0.7 / kPi * radiance * sphereIrradiance(p, {0, 1, 0}, centre, radius);
    };
    checkEveryLightSampling(scene, camera, exact, 11);
}

TEST_CASE("area lights: an emitter is seen from its front face, from both when doubleSided") {
    const Vec3 emission(1.0f, 2.0f, 3.0f);
    Camera camera = lookAt({0, 0, 0}, {0, 0, -1}, 0.9);
    for (bool frontFacing : {true, false})
        for (bool doubleSided : {false, true}) {
            CAPTURE(frontFacing);
            CAPTURE(doubleSided);
            Scene scene;
            uint32_t light = addMaterial(scene, Vec3(0.0f), emission, doubleSided);
            // Facing +z, the camera, unless the winding is turned.
            if (frontFacing) addQuad(scene, {-1, -1, -3}, {2, 0, 0}, {0, 2, 0}, light);
            else addQuad(scene, {-1, -1, -3}, {0, 2, 0}, {2, 0, 0}, light);
            RenderResult result = render(scene, camera, {.width = 9, .height = 9, .spp = 4});
            CHECK(result.colour.rgb(4, 4) == (frontFacing || doubleSided ? emission : Vec3(0.0f)));
        }
}

TEST_CASE("area lights: the same bits for 1 and 2 threads at any spp; the seed changes the noise") {
    Scene scene = loadGltf(sceneFile("radiometry/penumbra.gltf"));
    const Camera& camera = scene.cameras.front();
    for (LightSampling sampling : kLightSamplings)
        for (int spp : {1, 6}) {
            CAPTURE(std::string(lightSamplingName(sampling)));
            CAPTURE(spp);
            RenderResult one = render(scene, camera, {.width = 37, .height = 29, .spp = spp, .threads = 1, .seed = 3, .sampling = sampling});
            RenderResult two = render(scene, camera, {.width = 37, .height = 29, .spp = spp, .threads = 2, .seed = 3, .sampling = sampling});
            REQUIRE(one.colour.pixels.size() == two.colour.pixels.size());
            CHECK(std::memcmp(one.colour.pixels.data(), two.colour.pixels.data(), one.colour.pixels.size() * sizeof(float)) == 0);
            CHECK(one.shadow.rays == two.shadow.rays);
            RenderResult other = render(scene, camera, {.width = 37, .height = 29, .spp = spp, .threads = 2, .seed = 4, .sampling = sampling});
            CHECK(other.colour.pixels != one.colour.pixels);
        }
}

TEST_CASE("area lights: scenes without them ignore the seed and the light sampling at 1 spp") {
    Scene scene = loadGltf(sceneFile("cornell-box.gltf"));
    const Camera& camera = scene.cameras.front();
    RenderResult reference = render(scene, camera, {});
    CHECK(reference.shadow.rays > 0);
    for (LightSampling sampling : kLightSamplings) {
        RenderResult other = render(scene, camera, {.seed = 99, .sampling = sampling});
        CHECK(std::memcmp(other.colour.pixels.data(), reference.colour.pixels.data(), reference.colour.pixels.size() * sizeof(float)) == 0);
        CHECK(other.shadow.rays == reference.shadow.rays);
    }
}

TEST_CASE("area lights: a sample count out of range is an error") {
    Scene scene = loadGltf(sceneFile("radiometry/penumbra.gltf"));
    CHECK_THROWS_AS(render(scene, scene.cameras.front(), {.spp = 0}), Error);
    CHECK_THROWS_AS(render(scene, scene.cameras.front(), {.spp = kMaxSamplesPerPixel + 1}), Error);
}
