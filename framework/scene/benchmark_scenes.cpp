// Compiled with -ffp-contract=off: the meshes must come out bit for bit as the reference page
// specifies, and a fused multiply-add changes the last bits.
#include "framework/scene/benchmark_scenes.h"

#include "framework/core/error.h"
#include "framework/core/fnv1a.h"
#include "framework/core/pcg32.h"
#include "framework/scene/benchmark_rays.h"
#include "framework/scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtlab {

Bounds3f TriangleMesh::bounds() const {
    Bounds3f b;
    for (const auto& triangle : indices)
        for (uint32_t v : triangle) b.extend(positions[v]);
    return b;
}

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Sphere tessellation: a UV sphere with poles along world +-Y, 7 latitude bands and 12
// longitude segments: 2 + 6 * 12 vertices and 12 + 12 + 5 * 24 = 144 triangles.
constexpr int kLatitudeBands = 7;
constexpr int kLongitudeSegments = 12;
constexpr int kSphereflakeDepth = 4;

void addUvSphere(TriangleMesh& mesh, const Vec3& centre, float radius) {
    auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(centre + radius * Vec3(0.0f, 1.0f, 0.0f));
    mesh.positions.push_back(centre + radius * Vec3(0.0f, -1.0f, 0.0f));
    for (int i = 1; i < kLatitudeBands; ++i) {
        float theta = static_cast<float>(i) * (kPi / kLatitudeBands);
        for (int j = 0; j < kLongitudeSegments; ++j) {
            float phi = static_cast<float>(j) * (2.0f * kPi / kLongitudeSegments);
            Vec3 unit(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(centre + radius * unit);
        }
    }
    auto ring = [&](int i, int j) {
        return base + 2 + static_cast<uint32_t>((i - 1) * kLongitudeSegments + j % kLongitudeSegments);
    };
    uint32_t north = base, south = base + 1;
    constexpr int lastRing = kLatitudeBands - 1;
    for (int j = 0; j < kLongitudeSegments; ++j) mesh.indices.push_back({north, ring(1, j + 1), ring(1, j)});
    for (int j = 0; j < kLongitudeSegments; ++j)
        mesh.indices.push_back({south, ring(lastRing, j), ring(lastRing, j + 1)});
    for (int i = 1; i < lastRing; ++i) {
        for (int j = 0; j < kLongitudeSegments; ++j) {
            uint32_t a = ring(i, j), b = ring(i, j + 1), c = ring(i + 1, j), d = ring(i + 1, j + 1);
            mesh.indices.push_back({a, b, d});
            mesh.indices.push_back({a, d, c});
        }
    }
}

// Emits the sphere, then recurses depth-first into its 6 equator children (azimuth k * 60
// degrees) and its 3 upper children (azimuth 30 + k * 120 degrees, elevation 60 degrees).
void addSphereflake(TriangleMesh& mesh, const Vec3& centre, float radius, const Vec3& axis, int depth) {
    addUvSphere(mesh, centre, radius);
    if (depth == kSphereflakeDepth) return;
    Vec3 helper = std::fabs(axis.x) < 0.9f ? Vec3(1.0f, 0.0f, 0.0f) : Vec3(0.0f, 1.0f, 0.0f);
    Vec3 b = glm::normalize(glm::cross(axis, helper));
    Vec3 c = glm::cross(axis, b);
    float childRadius = radius / 3.0f;
    auto addChild = [&](const Vec3& direction) {
        addSphereflake(mesh, centre + direction * (radius + childRadius), childRadius, direction, depth + 1);
    };
    for (int k = 0; k < 6; ++k) {
        float phi = static_cast<float>(k) * (kPi / 3.0f);
        addChild(glm::normalize(b * std::cos(phi) + c * std::sin(phi)));
    }
    float elevation = kPi / 3.0f;
    for (int k = 0; k < 3; ++k) {
        float phi = kPi / 6.0f + static_cast<float>(k) * (2.0f * kPi / 3.0f);
        addChild(glm::normalize((b * std::cos(phi) + c * std::sin(phi)) * std::cos(elevation) +
                                axis * std::sin(elevation)));
    }
}

}  // namespace

TriangleMesh makeSphereflake() {
    TriangleMesh mesh;
    mesh.positions.reserve(7381 * 74);
    mesh.indices.reserve(kSphereflakeTriangles);
    addSphereflake(mesh, Vec3(0.0f), 1.0f, Vec3(0.0f, 1.0f, 0.0f), 0);
    return mesh;
}

TriangleMesh makeRandomSoup() {
    constexpr float kTriangleSize = 0.02f;
    Pcg32 rng(7, 54);
    TriangleMesh mesh;
    mesh.positions.reserve(3 * kRandomSoupTriangles);
    mesh.indices.reserve(kRandomSoupTriangles);
    for (uint32_t t = 0; t < kRandomSoupTriangles; ++t) {
        Vec3 centre;
        for (int axis = 0; axis < 3; ++axis) centre[axis] = rng.uniform();
        auto first = static_cast<uint32_t>(mesh.positions.size());
        for (int v = 0; v < 3; ++v) {
            Vec3 p;
            for (int axis = 0; axis < 3; ++axis) p[axis] = centre[axis] + (rng.uniform() - 0.5f) * kTriangleSize;
            mesh.positions.push_back(p);
        }
        mesh.indices.push_back({first, first + 1, first + 2});
    }
    return mesh;
}

const std::vector<std::string>& generatedSceneNames() {
    static const std::vector<std::string> names{"sphereflake", "randsoup"};
    return names;
}

TriangleMesh teapotInAStadium(const Scene& model) {
    Bounds3f box;
    for (const Vec3& p : model.triangles.positions) box.extend(p);
    Vec3 centre = box.centre(), extent = box.diagonal();
    float scale = 1.0f / std::max({extent.x, extent.y, extent.z, 1e-30f});
    TriangleMesh mesh;
    for (const Vec3& p : model.triangles.positions) mesh.positions.push_back((p - centre) * scale);
    mesh.indices = model.triangles.indices;
    auto base = static_cast<uint32_t>(mesh.positions.size());
    const float h = 100.0f;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back(Vec3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h));
    // Two triangles per face of the box, corner i having bit 0 = +x, bit 1 = +y, bit 2 = +z.
    const uint32_t faces[kStadiumWallTriangles][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                                      {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
    for (const auto& f : faces) mesh.indices.push_back({base + f[0], base + f[1], base + f[2]});
    return mesh;
}

Scene sceneFromMesh(TriangleMesh mesh, const std::string& sourcePath) {
    Bounds3f bounds = mesh.bounds();
    return sceneFromMesh(std::move(mesh), sourcePath, bounds);
}

Scene sceneFromMesh(TriangleMesh mesh, const std::string& sourcePath, const Bounds3f& bounds) {
    Scene scene;
    scene.sourcePath = sourcePath;
    size_t count = mesh.indices.size();
    scene.triangles.positions = std::move(mesh.positions);
    scene.triangles.indices = std::move(mesh.indices);
    scene.triangles.material.assign(count, 0);
    scene.triangles.smooth.assign(count, 0);
    scene.materials.push_back(Material{"white", Vec3(0.8f), Vec3(0.0f)});

    BenchmarkView view(bounds);
    Camera camera = view.camera();
    camera.name = "benchmark";
    scene.cameras.push_back(camera);

    // A light up and to the right of the eye, bright enough that a surface facing it at the
    // scene's centre reflects radiance of about its albedo: E = I / d^2 = pi at d = |eye - C|.
    float distance = glm::length(bounds.centre() - view.eye);
    PointLight light;
    light.name = "key";
    light.position = view.eye + 0.25f * distance * (view.right + view.up);
    light.intensity = Vec3(std::numbers::pi_v<float> * distance * distance);
    scene.lights.push_back(light);
    return scene;
}

Scene makeStadiumScene(const Scene& model) {
    TriangleMesh mesh = teapotInAStadium(model);
    Bounds3f modelBounds;
    for (size_t t = 0; t + kStadiumWallTriangles < mesh.indices.size(); ++t)
        for (uint32_t v : mesh.indices[t]) modelBounds.extend(mesh.positions[v]);
    return sceneFromMesh(std::move(mesh), "stadium (generated)", modelBounds);
}

Scene makeGeneratedScene(const std::string& name) {
    if (name == "sphereflake") return sceneFromMesh(makeSphereflake(), "sphereflake (generated)");
    if (name == "randsoup") return sceneFromMesh(makeRandomSoup(), "randsoup (generated)");
    throw Error("'" + name + "' is not a generated scene (valid: sphereflake, randsoup)");
}

Scene loadOrGenerateScene(const std::string& nameOrPath) {
    const auto& names = generatedSceneNames();
    if (std::find(names.begin(), names.end(), nameOrPath) != names.end()) return makeGeneratedScene(nameOrPath);
    return loadGltf(nameOrPath);
}

uint64_t triangleChecksum(const Scene& scene) {
    uint64_t hash = kFnv1aOffsetBasis;
    for (uint32_t i = 0; i < scene.triangleCount(); ++i)
        for (const Vec3& v : scene.triangleVertices(i)) {
            float xyz[3] = {v.x, v.y, v.z};
            hash = fnv1a64(xyz, sizeof xyz, hash);
        }
    return hash;
}

}  // namespace rtlab
