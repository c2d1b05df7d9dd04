// The Blender exporter without Blender (framework/blender/): the cut of emissive triangles, the
// conversions written into the script, one-line errors for what it cannot export, and the
// one-line error when Blender is missing. tests/test_blender_renders.cpp renders with Blender.
#include "framework/blender/blender_exporter.h"
#include "framework/blender/blender_reference.h"
#include "framework/blender/emitter_tessellation.h"
#include "framework/core/error.h"
#include "tests/blender_test_scenes.h"
#include "tests/cli_runner.h"
#include "tests/output_dirs.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

double area(const Vec3& a, const Vec3& b, const Vec3& c) {
    return 0.5 * glm::length(glm::cross(DVec3(b) - DVec3(a), DVec3(c) - DVec3(a)));
}

fs::path outputDir() { return test::outputDir("blender_export"); }

}  // namespace

TEST_CASE("emitter cut: k parts per edge, k^2 triangles with the winding and the area of the original") {
    // A 1 m right triangle has a hypotenuse of sqrt 2 = 1.414: ceil(1.414 / 0.5) = 3 parts,
    // ceil(1.414 / 1.5) = 1 (no cut).
    std::array<Vec3, 3> v{Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(1, 1, 1)};
    CHECK(cutsPerEdge(v, 0.5) == 3);
    CHECK(cutsPerEdge(v, 1.5) == 1);
    CHECK(cutsPerEdge({Vec3(0), Vec3(1e6f, 0, 0), Vec3(0, 1, 0)}, 0.5) == kMaxCutsPerEdge);
    TriangleCut cut = cutTriangle(v, {}, 3);
    REQUIRE(cut.indices.size() == 9);
    CHECK(cut.positions.size() == 10);  // (k + 1)(k + 2) / 2 lattice points
    DVec3 normal = glm::cross(DVec3(v[1]) - DVec3(v[0]), DVec3(v[2]) - DVec3(v[0]));
    double total = 0.0;
    for (const auto& t : cut.indices) {
        const Vec3 &a = cut.positions[t[0]], &b = cut.positions[t[1]], &c = cut.positions[t[2]];
        CHECK(glm::dot(glm::cross(DVec3(b) - DVec3(a), DVec3(c) - DVec3(a)), normal) > 0.0);  // same side emits
        for (const auto& [p, q] : {std::pair{a, b}, {b, c}, {c, a}})
            CHECK(glm::length(DVec3(q) - DVec3(p)) <= std::sqrt(2.0) / 3.0 + 1e-6);
        total += area(a, b, c);
    }
    CHECK(total == doctest::Approx(0.5).epsilon(1e-6));
    // The corners are exact, so neighbouring cut triangles meet where the originals did.
    CHECK(cut.positions.front() == v[0]);
    CHECK(std::count(cut.positions.begin(), cut.positions.end(), v[1]) == 1);
    CHECK(std::count(cut.positions.begin(), cut.positions.end(), v[2]) == 1);
}

TEST_CASE("blender export: the settings, the Z-up turn, watts for W/sr and radiance as strength x colour") {
    Scene scene = test::emitterScene(Vec3(3.0f, 1.5f, 0.75f));
    scene.triangles.positions[0] = Vec3(-4.0f, 0.1f, 4.0f);  // 0.1f is not 0.1
    scene.lights = {PointLight{"key", Vec3(0.7f, 2.0f, -0.4f), Vec3(15.0f, 12.0f, 9.0f)}};
    BlenderSettings settings;
    settings.samples = 64;
    settings.seed = 7;
    std::string script = exportBlenderScene(scene, scene.cameras.front(), settings);
    for (const char* line : {"cycles.light_sampling_threshold = 0.0", "cycles.max_bounces = 0", "cycles.filter_width = 0.01",
                             "cycles.use_denoising = False", "cycles.use_adaptive_sampling = False",
                             "cycles.use_animated_seed = False", "image.color_depth = \"32\"",
                             "scene.view_settings.view_transform = \"Standard\"",
                             "exact_settings(bpy.context.scene, 160, 120, 64, 7)", "data.shadow_soft_size = 0.0"})
        CHECK_MESSAGE(script.find(line) != std::string::npos, line);
    // glTF (x, y, z) is Blender (x, -z, y); the float32 vertex as its shortest decimal.
    CHECK(script.find("(-4, -4, 0.1)") != std::string::npos);
    // I = (15, 12, 9) W/sr: P = 4 pi 15 = 188.49555921538757 W, colour I / 15 = (1, 0.8, 0.6).
    CHECK(script.find("point_light(\"key\", (0.699999988079071, 0.4000000059604645, 2), 188.49555921538757, "
                      "(1, 0.8, 0.6))") != std::string::npos);
    CHECK(script.find("material(\"light\", (0, 0, 0), radiance=(3, 1.5, 0.75))") != std::string::npos);
    CHECK(script.find("double_sided=True") == std::string::npos);  // one-sided unless doubleSided
    // The 1 m light is cut in 3 parts per edge (hypotenuse 1.414 > 0.5): 2 x 9 triangles.
    CHECK(blenderSettingsText(settings) == "samples=64 seed=7 emitter-edge=0.5");
}

TEST_CASE("blender export: a sphere light, a smooth triangle without normals, a missing material are one line each") {
    auto expectError = [](const Scene& scene, const std::string& words) {
        try {
            exportBlenderScene(scene, scene.cameras.front(), BlenderSettings{});
            FAIL("exported");
        } catch (const Error& e) {
            std::string message = e.what();
            CHECK(message.rfind(scene.sourcePath + ": ", 0) == 0);
            CHECK(message.find(words) != std::string::npos);
            CHECK(message.find('\n') == std::string::npos);
        }
    };
    Scene sphereLight = test::emitterScene(Vec3(1.0f));
    sphereLight.spheres.push_back(Sphere{Vec3(0, 2, 0), 0.3f, 2});
    expectError(sphereLight, "a sphere light");
    CHECK(blenderUnsupported(sphereLight).find("sphere light") != std::string::npos);
    Scene smooth = test::emitterScene(Vec3(1.0f));
    smooth.triangles.smooth[0] = 1;
    expectError(smooth, "is smooth but the mesh has no normal per vertex");
    Scene unnamed = test::emitterScene(Vec3(1.0f));
    unnamed.triangles.material[1] = 9;
    expectError(unnamed, "primitive 1 names material 9 of 3");
    // A plain sphere is exported, as an exact point-cloud sphere.
    Scene ball = test::emitterScene(Vec3(1.0f));
    ball.spheres.push_back(Sphere{Vec3(0, 0.3f, 0), 0.3f, 1});
    CHECK(exportBlenderScene(ball, ball.cameras.front(), BlenderSettings{}).find("sphere(\"sphere 0\", (0, -0, 0.30000001192092896), 0.30000001192092896, materials[1])") !=
          std::string::npos);
}

TEST_CASE("rtlab export-blender: a malformed scene is one line and writes nothing") {
    fs::path bad = outputDir() / "malformed.gltf";
    std::ofstream(bad) << "{ not json";
    fs::path script = outputDir() / "never.py";
    fs::remove(script);
    test::CliResult malformed = test::runCli({"export-blender", bad.string(), "-o", script.string()});
    CHECK(malformed.status == 1);
    CHECK(malformed.err.rfind("rtlab: " + bad.string(), 0) == 0);
    CHECK(std::count(malformed.err.begin(), malformed.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(script));
    test::CliResult sphere = test::runCli(
        {"export-blender", RTLAB_SOURCE_DIR "/scenes/radiometry/sphere-light.gltf", "-o", script.string()});
    CHECK(sphere.status == 1);
    CHECK(sphere.err.find("a sphere light") != std::string::npos);
    CHECK_FALSE(fs::exists(script));
}

TEST_CASE("blender: a missing Blender is one line naming scripts/install-deps --blender") {
    setenv("RTLAB_BLENDER", "/nonexistent/blender", 1);
    Scene scene = test::emitterScene(Vec3(1.0f));
    try {
        renderBlenderReference(scene, scene.cameras.front(), BlenderSettings{}, outputDir() / "never.exr");
        FAIL("rendered without Blender");
    } catch (const Error& e) {
        std::string message = e.what();
        CHECK(message.find("cannot start /nonexistent/blender") == 0);
        CHECK(message.find("scripts/install-deps --blender") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
    test::CliResult refs = test::runCli({"refs", "--blender", "--scenes", RTLAB_SOURCE_DIR "/scenes", "--check"});
    CHECK(refs.status == 1);
    CHECK(refs.err.find("scripts/install-deps --blender") != std::string::npos);
    unsetenv("RTLAB_BLENDER");
}
