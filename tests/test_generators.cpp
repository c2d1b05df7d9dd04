// The procedural benchmark scenes and ray sets against the facts of
// docs/performance.md#scene-definitions and #ray-sets: triangle counts, bounds, spot rays,
// checksums. (The Embree hit counts of docs/performance.md#ray-sets are checked by the
// bench_reference_hits test in bench/.)
#include "framework/core/fnv1a.h"
#include "framework/scene/benchmark_rays.h"
#include "framework/scene/benchmark_scenes.h"
#include "framework/scene/gltf_loader.h"
#include "framework/scene/gltf_writer.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace rtlab;

namespace {

const std::string kBunnyPath = std::string(RTLAB_BINARY_DIR) + "/models/bunny.gltf";
const std::string kEnginePath = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// The reference page prints bounds with 6 significant digits.
void checkBounds(const Bounds3f& bounds, const Vec3& lower, const Vec3& upper) {
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(bounds.lower[axis] == doctest::Approx(lower[axis]).epsilon(5e-6));
        CHECK(bounds.upper[axis] == doctest::Approx(upper[axis]).epsilon(5e-6));
    }
}

// 9 significant digits identify a float exactly.
void checkExact(const Vec3& v, const char* x, const char* y, const char* z) {
    CHECK(v.x == std::strtof(x, nullptr));
    CHECK(v.y == std::strtof(y, nullptr));
    CHECK(v.z == std::strtof(z, nullptr));
}

void checkRaySet(const std::vector<Ray>& rays, const Bounds3f& originBounds) {
    REQUIRE(rays.size() == (1u << 20));
    for (size_t i = 0; i < rays.size(); i += 997) {
        const Ray& ray = rays[i];
        CHECK(ray.tMin == 0.0f);
        CHECK(ray.tMax == kInfinity);
        CHECK(glm::length(ray.direction) == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(originBounds.contains(Bounds3f(ray.origin)));
    }
}

}  // namespace

TEST_CASE("FNV-1a 64 gives the published test vectors") {
    CHECK(fnv1a64("", 0) == 0xcbf29ce484222325ull);
    CHECK(fnv1a64("a", 1) == 0xaf63dc4c8601ec8cull);
    CHECK(fnv1a64("foobar", 6) == 0x85944171f73967e8ull);
}

TEST_CASE("sphereflake: 7,381 spheres of 144 triangles within the reference bounds") {
    TriangleMesh mesh = makeSphereflake();
    CHECK(mesh.indices.size() == 1'062'864);
    CHECK(mesh.positions.size() == 7381 * 74);
    checkBounds(mesh.bounds(), Vec3(-1.72929f, -1.0f, -1.91106f), Vec3(1.78886f, 1.75366f, 1.91106f));
    // The root sphere comes first: its north pole, then the first vertex of ring 1.
    CHECK(mesh.positions[0] == Vec3(0.0f, 1.0f, 0.0f));
    CHECK(mesh.positions[2].y == doctest::Approx(std::cos(M_PI / 7)).epsilon(1e-6));
}

TEST_CASE("randsoup: 2^20 triangles of edge below 0.02*sqrt(3) around centres in [0,1)^3") {
    TriangleMesh mesh = makeRandomSoup();
    REQUIRE(mesh.indices.size() == (1u << 20));
    Bounds3f bounds = mesh.bounds();
    CHECK(Bounds3f(Vec3(-0.01f), Vec3(1.01f)).contains(bounds));
    CHECK(bounds.diagonal().x > 1.0f);
    const auto& t = mesh.indices.back();
    CHECK(glm::length(mesh.positions[t[0]] - mesh.positions[t[1]]) < 0.02f * std::sqrt(3.0f));
}

TEST_CASE("ray sets: 2^20 unit rays from the eye or from inside the bounds") {
    Scene scene = makeGeneratedScene("sphereflake");
    Bounds3f bounds = scene.bounds();
    BenchmarkView view(bounds);
    checkRaySet(makePrimaryRays(bounds), Bounds3f(view.eye));
    checkRaySet(makeIncoherentRays(bounds), bounds);
}

TEST_CASE("a generated scene survives the glTF round trip bit for bit, camera and light included") {
    Scene scene = makeGeneratedScene("sphereflake");
    auto path = std::filesystem::temp_directory_path() / "rtlab_test_sphereflake.glb";
    writeGltf(scene, path.string());
    Scene loaded = loadGltf(path.string());
    std::filesystem::remove(path);
    CHECK(loaded.triangleCount() == scene.triangleCount());
    CHECK(triangleChecksum(loaded) == triangleChecksum(scene));
    REQUIRE(loaded.cameras.size() == 1);
    REQUIRE(loaded.lights.size() == 1);
    const Camera& camera = loaded.cameras[0];
    CHECK(glm::length(camera.position - scene.cameras[0].position) < 1e-5);
    CHECK(glm::dot(camera.forward, scene.cameras[0].forward) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(glm::dot(camera.up, scene.cameras[0].up) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(loaded.lights[0].intensity.x == doctest::Approx(scene.lights[0].intensity.x).epsilon(1e-6));
}

TEST_CASE("bunny (scripts/fetch-models): counts, bounds and the reference spot rays") {
    REQUIRE_MESSAGE(std::filesystem::exists(kBunnyPath), kBunnyPath << " is missing: run scripts/fetch-models");
    Scene bunny = loadGltf(kBunnyPath);
    CHECK(bunny.triangleCount() == 3674);
    Bounds3f bounds = bunny.bounds();
    checkBounds(bounds, Vec3(-4.95848f, -0.003149f, -3.72983f), Vec3(4.94885f, 9.65475f, 3.81064f));

    std::vector<Ray> primary = makePrimaryRays(bounds);
    const Ray& centre = primary[512 * 1024 + 512];
    checkExact(centre.origin, "7.44622707", "11.0349998", "12.4588032");
    checkExact(centre.direction, "-0.472437203", "-0.394426942", "-0.788181722");
    std::vector<Ray> incoherent = makeIncoherentRays(bounds);
    checkExact(incoherent[0].origin, "4.71415234", "3.63370156", "3.35286117");
    checkExact(incoherent[0].direction, "-0.396167964", "0.819290996", "-0.414503455");
}

TEST_CASE("engine (assimp-testmodels): 121,496 triangles within the reference bounds") {
    Scene engine = loadGltf(kEnginePath);
    CHECK(engine.triangleCount() == 121'496);
    checkBounds(engine.bounds(), Vec3(-371.692f, -180.972f, -140.0f), Vec3(371.692f, 92.0416f, 128.0f));
}
