// The glTF loader on hand-written files (tests/data/make-test-data.py says what is in them;
// the expected values below are worked out by hand from those numbers) and on the committed
// scenes.
#include "framework/core/error.h"
#include "framework/scene/emitters.h"
#include "framework/scene/gltf_loader.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

using namespace rtlab;

namespace {

std::string dataFile(const std::string& name) { return std::string(RTLAB_SOURCE_DIR) + "/tests/data/" + name; }
std::string sceneFile(const std::string& name) { return std::string(RTLAB_SOURCE_DIR) + "/scenes/" + name; }

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool hasFeature(const Scene& scene, const std::string& feature) {
    return std::find(scene.featuresUsed.begin(), scene.featuresUsed.end(), feature) != scene.featuresUsed.end();
}

void checkVec(const Vec3& actual, const Vec3& expected, float epsilon = 1e-6f) {
    CHECK(actual.x == doctest::Approx(expected.x).epsilon(epsilon));
    CHECK(actual.y == doctest::Approx(expected.y).epsilon(epsilon));
    CHECK(actual.z == doctest::Approx(expected.z).epsilon(epsilon));
}

void checkVec(const DVec3& actual, const DVec3& expected) {
    checkVec(Vec3(actual), Vec3(expected));
}

// The world-space triangle whose first vertex is `first` (triangle order follows node order,
// which the test does not want to depend on).
std::array<Vec3, 3> triangleStartingAt(const Scene& scene, const Vec3& first, uint32_t* index) {
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        auto v = scene.triangleVertices(t);
        if (glm::length(v[0] - first) < 1e-5f) {
            *index = t;
            return v;
        }
    }
    FAIL("no triangle starts at (" << first.x << ", " << first.y << ", " << first.z << ")");
    return {};
}

// Loading `path` fails with one rtlab::Error line that names the file and contains `problem`.
void checkRejectedPath(const std::string& path, const std::string& problem) {
    CAPTURE(path);
    try {
        loadGltf(path);
        FAIL("loaded without an error");
    } catch (const Error& e) {
        std::string message = e.what();
        CAPTURE(message);
        CHECK(message.rfind(path + ": ", 0) == 0);
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.find(problem) != std::string::npos);
    }
}

void checkRejected(const std::string& name, const std::string& problem) { checkRejectedPath(dataFile(name), problem); }

void checkHierarchy(const Scene& scene) {
    REQUIRE(scene.triangleCount() == 4);
    REQUIRE(scene.spheres.size() == 1);
    REQUIRE(scene.materials.size() == 3);  // red, glow and the default one
    REQUIRE(scene.lights.size() == 1);
    REQUIRE(scene.cameras.size() == 1);

    // root = T(10,0,0) * Rz(90 deg) * S(2); Rz maps (x, y, z) to (-y, x, z).
    uint32_t t = 0;
    SUBCASE("matrix child, u8 indices, interleaved normals") {
        auto v = triangleStartingAt(scene, {10, 0, 10}, &t);  // local (0,0,0) + (0,0,5)
        checkVec(v[1], {10, 2, 10});
        checkVec(v[2], {8, 0, 10});
        CHECK(scene.triangles.material[t] == 0);
        CHECK(scene.triangles.smooth[t] == 1);
        // Normal (0.6, 0.8, 0) under a similarity: just rotated.
        checkVec(scene.triangles.normals[scene.triangles.indices[t][0]], {-0.8f, 0.6f, 0.0f});
    }
    SUBCASE("TRS child with non-uniform scale, u16 indices after an accessor byteOffset") {
        auto v = triangleStartingAt(scene, {10, 0, -2}, &t);  // S(3,1,1), then +(0,0,-1)
        checkVec(v[1], {10, 6, -2});
        checkVec(v[2], {8, 0, -2});
        CHECK(scene.triangles.material[t] == 1);
        CHECK(scene.triangles.smooth[t] == 1);
        // Inverse transpose: (0.6, 0.8, 0) / (3, 1, 1) = (0.2, 0.8, 0), rotated to (-0.8, 0.2, 0).
        float s = 1.0f / std::sqrt(0.68f);
        checkVec(scene.triangles.normals[scene.triangles.indices[t][2]], {-0.8f * s, 0.2f * s, 0.0f}, 1e-5f);
    }
    SUBCASE("u32 indices, no normals, default material") {
        auto v = triangleStartingAt(scene, {0, 0, 0}, &t);
        checkVec(v[1], {0, 1, 0});
        checkVec(v[2], {1, 0, 0});
        CHECK(scene.triangles.smooth[t] == 0);
        CHECK(scene.materials[scene.triangles.material[t]].albedo == Vec3(0.8f));
    }
    SUBCASE("non-indexed, accessor byteOffset skips a NaN vertex") {
        auto v = triangleStartingAt(scene, {0, 3, 0}, &t);
        checkVec(v[1], {0, 3, 1});
        checkVec(v[2], {1, 3, 0});
        CHECK(scene.triangles.smooth[t] == 0);
    }
    SUBCASE("materials: baseColorFactor, emissiveFactor * emissiveStrength") {
        checkVec(scene.materials[0].albedo, {0.8f, 0.1f, 0.1f});
        checkVec(scene.materials[0].emission, {0, 0, 0});
        checkVec(scene.materials[1].emission, {4.0f, 2.0f, 1.0f});
        CHECK(hasFeature(scene, "KHR_materials_emissive_strength"));
    }
    SUBCASE("point light: 100 cd -> 100/683 W/sr, placed through its parent") {
        const PointLight& light = scene.lights[0];
        CHECK(light.name == "lamp");
        checkVec(light.position, {10, 0, 2});
        checkVec(light.intensity, {100.0f / 683.0f, 50.0f / 683.0f, 25.0f / 683.0f});
        CHECK(hasFeature(scene, "KHR_lights_punctual"));
    }
    SUBCASE("sphere from extras: centre through the hierarchy, radius scaled 2 * 1.5") {
        const Sphere& sphere = scene.spheres[0];
        checkVec(sphere.centre, {10, 2, 0});
        CHECK(sphere.radius == doctest::Approx(1.5));
        CHECK(sphere.material == 1);
        CHECK(scene.primitiveCount() == 5);
        CHECK(scene.isSphere(4));
        CHECK(hasFeature(scene, "extras.rtlab.sphere"));
    }
    SUBCASE("camera: yfov, aspect, name, pose from the node (90 deg about +Y)") {
        const Camera& camera = scene.camera("cam");
        CHECK(camera.yfov == 0.5);
        CHECK(camera.aspectRatio == 1.5);
        checkVec(camera.position, {1, 2, 3});
        CHECK(glm::length(camera.forward - DVec3(-1, 0, 0)) < 1e-12);
        CHECK(glm::length(camera.up - DVec3(0, 1, 0)) < 1e-12);
        CHECK(&scene.camera("") == &camera);
        CHECK_THROWS_AS(scene.camera("nope"), Error);
    }
    SUBCASE("POINTS primitive skipped and recorded") {
        CHECK(hasFeature(scene, "skipped primitives of mode POINTS"));
    }
}

}  // namespace

TEST_CASE("glTF loader: hierarchy.gltf (JSON with an embedded buffer)") {
    checkHierarchy(loadGltf(dataFile("hierarchy.gltf")));
}

TEST_CASE("glTF loader: hierarchy.glb (binary) gives the same scene") {
    checkHierarchy(loadGltf(dataFile("hierarchy.glb")));
}

TEST_CASE("glTF loader: malformed files give one clear line naming the file") {
    checkRejected("truncated.glb", "");
    checkRejected("bad-json.gltf", "parse error");
    checkRejected("index-out-of-range.gltf", "index 3 is out of range");
    checkRejected("missing-buffer.gltf", "missing.bin");
    checkRejected("nan-vertex.gltf", "mesh 0 'tri'");
    checkRejected("nan-vertex.gltf", "non-finite position");
    checkRejected("accessor-overrun.gltf", "reach past the end");
    checkRejected("spot-light.gltf", "spot lights are not supported");
    checkRejected("nonuniform-sphere.gltf", "non-uniform scale");
    checkRejected("cycle.gltf", "reached twice");
    checkRejected("no-such-file.gltf", "cannot open");
}

TEST_CASE("glTF loader: the committed scenes") {
    struct Expected {
        const char* name;
        uint32_t triangles;
        size_t spheres;
        size_t lights;
        bool normals;
    };
    // What scripts/make-scenes.py builds: quads are 2 triangles, boxes 12, a UV sphere of 12
    // bands and 24 segments 24 * (2 * 12 - 2) = 528.
    const Expected scenes[] = {
        {"cornell-box.gltf", 5 * 2 + 2 * 12, 0, 1, false},
        {"spheres.gltf", 2, 5, 1, false},
        {"smooth-mesh.gltf", 2 + 2 * 528, 0, 1, true},
        {"light-behind.gltf", 2 + 2 + 12, 0, 1, false},
        {"multi-light.gltf", 2 + 12, 1, 3, false},
        {"radiometry/penumbra.gltf", 2 + 2 + 2, 0, 0, false},
        {"radiometry/sphere-light.gltf", 2 + 12, 2, 0, false},
        {"radiometry/mixed-lights.gltf", 2 + 12 + 2, 1, 2, false},
        {"radiometry/closed-form.gltf", 2 + 2, 0, 0, false},
    };
    for (const Expected& expected : scenes) {
        CAPTURE(expected.name);
        Scene scene = loadGltf(sceneFile(expected.name));
        CHECK(scene.triangleCount() == expected.triangles);
        CHECK(scene.spheres.size() == expected.spheres);
        CHECK(scene.lights.size() == expected.lights);
        CHECK(scene.cameras.size() == 1);
        CHECK(scene.cameras[0].aspectRatio == doctest::Approx(4.0 / 3.0));
        CHECK(!scene.triangles.normals.empty() == expected.normals);
    }
    // The Cornell box light: 1000 cd of colour (1, 0.9, 0.75).
    Scene cornell = loadGltf(sceneFile("cornell-box.gltf"));
    checkVec(cornell.lights[0].intensity, Vec3(1.0f, 0.9f, 0.75f) * (1000.0f / 683.0f));
    checkVec(cornell.lights[0].position, {0.0f, 1.375f, 0.25f});
}

TEST_CASE("glTF loader: lights in watts, emissive materials, doubleSided (scenes/radiometry/mixed-lights.gltf)") {
    Scene scene = loadGltf(sceneFile("radiometry/mixed-lights.gltf"));
    // 150 W of colour (1, 0.8, 0.6) from extras.rtlab.power: I = 150 / 4 pi W/sr per unit colour.
    const PointLight& bulb = scene.lights[0];
    CHECK(bulb.name == "warm bulb");
    checkVec(bulb.intensity, Vec3(1.0f, 0.8f, 0.6f) * float(150.0 / (4.0 * std::numbers::pi)));
    CHECK(hasFeature(scene, "extras.rtlab.power"));
    // The other light is in candela: 2500 cd -> 2500 / 683 W/sr.
    checkVec(scene.lights[1].intensity, Vec3(0.6f, 0.7f, 1.0f) * (2500.0f / 683.0f));
    // The panel: emissiveFactor (0.6, 0.8, 1) times emissiveStrength 8, both faces.
    std::vector<Emitter> emitters = findEmitters(scene);
    REQUIRE(emitters.size() == 2);
    const Material& panel = scene.materials[scene.materialOf(emitters[0].prim)];
    checkVec(panel.emission, {4.8f, 6.4f, 8.0f});
    CHECK(panel.doubleSided);
    CHECK(emitters[0].twoSided);
    // Each triangle is half of the 0.8 m x 0.6 m panel; power = pi L A with L the mean of the
    // channels, twice for two sides.
    CHECK(emitters[0].area == doctest::Approx(0.24).epsilon(1e-4));
    CHECK(emitters[0].power == doctest::Approx(2.0 * std::numbers::pi * 6.4 * emitters[0].area).epsilon(1e-6));
}

TEST_CASE("glTF loader: a sphere light and one-sided triangles (scenes/radiometry)") {
    Scene spheres = loadGltf(sceneFile("radiometry/sphere-light.gltf"));
    std::vector<Emitter> emitters = findEmitters(spheres);
    REQUIRE(emitters.size() == 1);
    CHECK(spheres.isSphere(emitters[0].prim));
    CHECK(emitters[0].area == doctest::Approx(4.0 * std::numbers::pi * 0.16));
    CHECK_FALSE(emitters[0].twoSided);

    Scene square = loadGltf(sceneFile("radiometry/closed-form.gltf"));
    REQUIRE(findEmitters(square).size() == 2);
    for (const Emitter& e : findEmitters(square)) {
        CHECK_FALSE(e.twoSided);
        CHECK(e.area == doctest::Approx(0.5));
        // The front face looks down: the light is seen from below, not from above.
        auto v = square.triangleVertices(e.prim);
        Vec3 front = glm::cross(v[1] - v[0], v[2] - v[0]);
        checkVec(emittedRadiance(square, e.prim, glm::normalize(front), {0, -1, 0}), {4, 4, 4});
        checkVec(emittedRadiance(square, e.prim, glm::normalize(front), {0, 1, 0}), {0, 0, 0});
    }
}

TEST_CASE("glTF loader: a light's power must be a finite, non-negative number of watts") {
    std::string path = std::string(RTLAB_BINARY_DIR) + "/tests/bad-power.gltf";
    for (const char* power : {"-1", "\"bright\"", "[100]"}) {
        CAPTURE(power);
        std::ofstream(path) << R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
            "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "extras": {"rtlab": {"power": )" << power
                            << R"(}}}]}}, "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}}]})";
        checkRejectedPath(path, "extras.rtlab.power must be a finite number of watts");
    }
}

TEST_CASE("glTF scenes: the committed files are exactly what scripts/make-scenes.py writes") {
    std::string out = std::string(RTLAB_BINARY_DIR) + "/tests/make-scenes-check";
    std::filesystem::remove_all(out);
    std::string command = "python3 '" + std::string(RTLAB_SOURCE_DIR) + "/scripts/make-scenes.py' '" + out + "' > /dev/null";
    REQUIRE(std::system(command.c_str()) == 0);
    int compared = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(out)) {
        if (!entry.is_regular_file()) continue;
        std::string name = std::filesystem::relative(entry.path(), out).string();
        CAPTURE(name);
        bool identical = fileBytes(entry.path().string()) == fileBytes(sceneFile(name));
        CHECK(identical);  // if not: run scripts/make-scenes.py and commit its output
        ++compared;
    }
    CHECK(compared == 9);
}
