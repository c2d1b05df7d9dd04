// The POV-Ray exporter against live POV-Ray: a rendered scene against the closed form
// rho/pi * I * cos / d^2 (+ emission), and a trace() hit set against the oracle.
#include "framework/accel/accelerator.h"
#include "framework/core/error.h"
#include "framework/oracle/oracle.h"
#include "framework/pov/pov_exporter.h"
#include "framework/pov/pov_reference.h"
#include "framework/pov/pov_trace.h"
#include "framework/pov/povray_process.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/render/renderer.h"
#include "tests/output_dirs.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

using namespace rtlab;
namespace fs = std::filesystem;

static fs::path outputDir() { return test::outputDir("pov_export"); }

// A quad in the plane z = -3 facing the camera at the origin, made of two triangles: the left
// one plain diffuse, the right one with a black red channel and emission (which POV-Ray can
// only express through the averaged-texture route of the exporter). One point light.
static Scene litQuad() {
    Scene scene;
    scene.sourcePath = "lit-quad (test)";
    scene.triangles.positions = {{-4, -3, -3}, {4, -3, -3}, {4, 3, -3}, {-4, 3, -3}};
    scene.triangles.indices = {{0, 1, 3}, {1, 2, 3}};
    scene.triangles.material = {0, 1};
    scene.triangles.smooth = {0, 0};
    scene.materials = {Material{"diffuse", Vec3(0.8f, 0.6f, 0.3f), Vec3(0.0f)},
                       Material{"glowing", Vec3(0.0f, 0.5f, 0.2f), Vec3(0.25f, 0.1f, 0.0f)}};
    scene.lights = {PointLight{"key", Vec3(0.7f, -0.4f, 0.5f), Vec3(15.0f, 12.0f, 9.0f)}};
    Camera camera;
    camera.name = "front";
    camera.yfov = 0.9;
    scene.cameras = {camera};
    return scene;
}

static double code16(double value) { return std::floor(std::clamp(value, 0.0, 1.0) * 65535.0 + 0.5); }

TEST_CASE("pov export: POV-Ray renders rho/pi * I * cos/d^2 + emission at every pixel (64x48)") {
    Scene scene = litQuad();
    const Camera& camera = scene.cameras.front();
    constexpr int kWidth = 64, kHeight = 48;
    fs::path png = outputDir() / "lit_quad.png";
    renderPovReference(scene, camera, kWidth, kHeight, png);
    Image image = readImage(png.string());
    REQUIRE(image.width == kWidth);
    REQUIRE(image.height == kHeight);

    Oracle oracle(scene);
    int worst = 0, exact = 0;
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            OracleHit hit = oracle.closestHit(OracleRay::from(camera.generateRay(i, j, kWidth, kHeight)));
            REQUIRE(hit.hit);
            const Material& material = scene.materials[hit.prim];
            const PointLight& light = scene.lights.front();
            DVec3 toLight = DVec3(light.position) - hit.point;
            double d2 = glm::dot(toLight, toLight);
            double cosine = toLight.z / std::sqrt(d2);  // the quad's normal is +z
            for (int c = 0; c < 3; ++c) {
                double expected = material.albedo[c] / std::numbers::pi * light.intensity[c] * cosine / d2 +
                                  material.emission[c];
                int difference = static_cast<int>(std::abs(code16(expected) - code16(image.at(i, j, c))));
                worst = std::max(worst, difference);
                exact += difference == 0;
            }
        }
    }
    MESSAGE("channel codes equal to the closed form: " << exact << " of " << 3 * kWidth * kHeight
                                                       << ", worst difference " << worst << " code");
    CHECK(worst <= 1);  // POV-Ray's colours are float32: off by one code at rounding boundaries
    CHECK(exact >= 3 * kWidth * kHeight * 99 / 100);

    // The centre pixel of the brief, by itself.
    Ray centre = camera.generateRay(kWidth / 2, kHeight / 2, kWidth, kHeight);
    OracleHit hit = oracle.closestHit(OracleRay::from(centre));
    REQUIRE(hit.hit);
    DVec3 toLight = DVec3(scene.lights[0].position) - hit.point;
    double d2 = glm::dot(toLight, toLight);
    double expectedGreen = scene.materials[hit.prim].albedo.g / std::numbers::pi * 12.0 *
                               (toLight.z / std::sqrt(d2)) / d2 +
                           scene.materials[hit.prim].emission.g;
    CHECK(std::abs(code16(expectedGreen) - code16(image.at(kWidth / 2, kHeight / 2, 1))) <= 1.0);
}

TEST_CASE("pov export: the exported file prints float32 vertices exactly and names its render command") {
    Scene scene = litQuad();
    scene.triangles.positions[0] = Vec3(0.1f, -3.0f, -3.0f);  // 0.1f is not 0.1
    std::string text = exportPovScene(scene, scene.cameras.front(), 320, 240);
    CHECK(text.find("#version 3.7;") != std::string::npos);
    CHECK(text.find("+W320 +H240 -A -D +FN16 File_Gamma=1.0") != std::string::npos);
    CHECK(text.find("<0.1,-3,-3>") != std::string::npos);  // mesh2: shortest float32 decimal
    std::string trace = exportPovTraceObject(scene, "S");
    CHECK(trace.find("<0.10000000149011612,-3,-3>") != std::string::npos);  // triangle{}: the exact double
}

TEST_CASE("pov export: a smooth mesh without vertex normals is refused with one line") {
    Scene scene = litQuad();
    scene.triangles.smooth = {1, 0};
    CHECK_THROWS_AS(exportPovScene(scene, scene.cameras.front(), 64, 48), Error);
}

// Two touching boxes' worth of triangles and two spheres, one of them partly inside a box.
static Scene traceScene() {
    Scene scene;
    scene.sourcePath = "trace-scene (test)";
    auto addBox = [&scene](Vec3 lower, Vec3 upper) {
        auto base = static_cast<uint32_t>(scene.triangles.positions.size());
        for (int k = 0; k < 8; ++k)
            scene.triangles.positions.push_back(
                {(k & 1) ? upper.x : lower.x, (k & 2) ? upper.y : lower.y, (k & 4) ? upper.z : lower.z});
        const uint32_t faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
        for (const auto& f : faces) {
            scene.triangles.indices.push_back({base + f[0], base + f[1], base + f[2]});
            scene.triangles.material.push_back(0);
            scene.triangles.smooth.push_back(0);
        }
    };
    addBox({-1.3f, -0.7f, -2.1f}, {0.4f, 0.9f, -0.2f});
    addBox({0.4f, -0.7f, -1.7f}, {1.9f, 0.1f, -0.6f});
    scene.spheres = {Sphere{{0.4f, 1.2f, -1.1f}, 0.55f, 0}, Sphere{{-1.1f, -0.9f, 0.3f}, 0.37f, 0}};
    scene.materials = {Material{}};
    Camera camera;
    camera.position = {0.5, 0.8, 4.0};
    camera.forward = glm::normalize(DVec3(-0.1, -0.2, -1.0));
    scene.cameras = {camera};
    return scene;
}

TEST_CASE("pov trace: POV-Ray's trace() agrees with the oracle on 300 rays") {
    Scene scene = traceScene();
    std::vector<OracleRay> rays = makeHitSetRays(scene, scene.cameras.front(), 300, 7);
    REQUIRE(rays.size() == 300);
    std::vector<PovTraceHit> hits = traceWithPovray(scene, rays);
    HitSetComparison comparison = compareWithOracle(scene, rays, hits);
    for (const std::string& line : comparison.mismatches) MESSAGE(line);
    MESSAGE(comparison.compared << " rays compared, " << comparison.nearEdge << " near an edge, "
                                << comparison.bothHit << " hits, max point error " << comparison.maxPointError
                                << ", max normal error " << comparison.maxNormalError);
    CHECK(comparison.agrees());
    CHECK(comparison.compared >= 290);
    CHECK(comparison.bothHit >= 100);
    // Both sides intersect the same double-precision shapes: far below the float32 bound.
    CHECK(comparison.maxPointError < 1e-9);
    CHECK(comparison.maxNormalError < 1e-9);
}

TEST_CASE("pov export: bad input is one line; a failed POV-Ray run names its log, which is kept") {
    Scene empty;
    empty.sourcePath = "empty (test)";
    std::vector<OracleRay> rays{OracleRay{{0, 0, 0}, {0, 0, 1}}};
    CHECK_THROWS_AS(traceWithPovray(empty, rays), Error);

    Scene scene = litQuad();
    scene.materials.pop_back();  // the right triangle names a missing material
    CHECK_THROWS_WITH_AS(exportPovScene(scene, scene.cameras.front(), 8, 6),
                         doctest::Contains("names material 1 of 1"), Error);

    TemporaryDirectory work("rtlab-test-broken-pov");
    std::ofstream(work.path() / "broken.pov") << "#version 3.7;\nsphere { <0,0,0>, }\n";
    std::string message;
    try {
        runPovrayOrThrow({"-Ibroken.pov", "+W8", "+H6", "-D"}, work, "rendering broken.pov");
    } catch (const Error& e) {
        message = e.what();
    }
    MESSAGE(message);
    CHECK(message.find("povray failed") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    fs::path log = work.path() / "povray.log";
    CHECK(message.find(log.string()) != std::string::npos);
    CHECK(fs::exists(log));
    fs::remove_all(work.path());  // kept for the user; this test cleans up after itself
}

// A floor lit by a light 1 above it, and a small card just below the light that shadows the
// floor's x > 0 half. POV-Ray ignores occluders within 1e-3 of the light (SHADOW_TOLERANCE);
// rtlab stops shadow rays kShadowEpsilon = 1e-4 of their length short of the light.
static Scene cardUnderLight(float gap) {
    Scene scene;
    scene.sourcePath = "card under a light (test)";
    scene.triangles.positions = {{-3, 0, -3}, {3, 0, -3}, {3, 0, 3}, {-3, 0, 3},
                                 {0, 1 - gap, -0.01f}, {0.01f, 1 - gap, -0.01f}, {0.01f, 1 - gap, 0.01f},
                                 {0, 1 - gap, 0.01f}};
    scene.triangles.indices = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    scene.triangles.material = {0, 0, 0, 0};
    scene.triangles.smooth = {0, 0, 0, 0};
    scene.materials = {Material{"grey", Vec3(0.8f), Vec3(0.0f)}};
    scene.lights = {PointLight{"", Vec3(0.0f, 1.0f, 0.0f), Vec3(2.0f)}};
    Camera camera;
    camera.position = {0.0, 0.6, 2.5};
    camera.forward = glm::normalize(DVec3(0.0, -0.6, -2.5));
    scene.cameras = {camera};
    return scene;
}

static ImageComparison renderBothAndCompare(const Scene& scene, const std::string& name) {
    constexpr int kWidth = 64, kHeight = 48;
    fs::path pov = outputDir() / (name + ".pov.png");
    renderPovReference(scene, scene.cameras.front(), kWidth, kHeight, pov);
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator({.name = "brute"});
    accelerator->build(primitives);
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.progress = false;
    fs::path ours = outputDir() / (name + ".rtlab.png");
    writeImage(ours.string(), Renderer(scene, scene.cameras.front(), *accelerator).render(settings).colour);
    return compareImages(ours.string(), pov.string(), 2.0);
}

TEST_CASE("pov export: shadow tolerance - an occluder within 1e-3 of the light shadows only in rtlab") {
    // 4e-3 from the light: both renderers shadow the x > 0 half; only pixels on the shadow's
    // border may differ.
    ImageComparison far = renderBothAndCompare(cardUnderLight(4e-3f), "card_far");
    MESSAGE("card 4e-3 below the light: " << far.pixelsOverThreshold << " of " << far.pixelCount
                                          << " pixels over 2 codes");
    CHECK(far.medianPixelCodes == 0.0);
    CHECK(far.shareOverThreshold() < 0.02);

    // 2e-4 from the light (every shadow ray meets the card within 8.7e-4 of the light):
    // POV-Ray ignores the card, rtlab's shadow rays reach 1e-4 of their length from the light.
    ImageComparison near = renderBothAndCompare(cardUnderLight(2e-4f), "card_near");
    MESSAGE("card 2e-4 below the light: " << near.pixelsOverThreshold << " of " << near.pixelCount
                                          << " pixels over 2 codes, max " << near.maxCodes() << " codes");
    CHECK(near.shareOverThreshold() > 0.3);
    CHECK(near.maxCodes() > 10000.0);
}

TEST_CASE("pov export: POV-Ray's Trace Time of a reference render is read from its log") {
    Scene scene = litQuad();
    double seconds = timePovReference(scene, scene.cameras.front(), 64, 48);
    CHECK(seconds >= 0.0);
    CHECK(seconds < kPovrayTimeLimitSeconds);
    CHECK_THROWS_AS(timePovReference(scene, scene.cameras.front(), 0, 48), Error);
}
