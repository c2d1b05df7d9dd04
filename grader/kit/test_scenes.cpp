#include "grader/kit/test_scenes.h"

#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/scene/benchmark_scenes.h"
#include "framework/scene/gltf_loader.h"
#include "framework/scene/icosphere_mesh.h"

#include <cmath>
#include <filesystem>

namespace rtlab::grader {

SceneBuilder::SceneBuilder() { scene_.materials.push_back(Material{"grey", Vec3(0.8f), Vec3(0.0f)}); }

void SceneBuilder::addTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    auto base = static_cast<uint32_t>(scene_.triangles.positions.size());
    scene_.triangles.positions.insert(scene_.triangles.positions.end(), {a, b, c});
    scene_.triangles.indices.push_back({base, base + 1, base + 2});
    scene_.triangles.material.push_back(0);
    scene_.triangles.smooth.push_back(0);
}

void SceneBuilder::addMesh(const std::vector<Vec3>& positions, const std::vector<std::array<uint32_t, 3>>& indices) {
    auto base = static_cast<uint32_t>(scene_.triangles.positions.size());
    scene_.triangles.positions.insert(scene_.triangles.positions.end(), positions.begin(), positions.end());
    for (const auto& t : indices) {
        scene_.triangles.indices.push_back({base + t[0], base + t[1], base + t[2]});
        scene_.triangles.material.push_back(0);
        scene_.triangles.smooth.push_back(0);
    }
}

void SceneBuilder::addSphere(const Vec3& centre, float radius) { scene_.spheres.push_back(Sphere{centre, radius, 0}); }

namespace {

float uniform(Pcg32& rng, float lo, float hi) { return lo + (hi - lo) * rng.uniform(); }

// An axis-aligned box [lo, hi] as 12 triangles with shared corners.
void addBox(SceneBuilder& builder, const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i) corners.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    builder.addMesh(corners, {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}});
}

}  // namespace

TestScene icosphere(int levels) {
    SceneBuilder builder;
    IndexedMesh mesh = icosphereMesh(levels);
    builder.addMesh(mesh.positions, mesh.triangles);
    TestScene s{"icosphere-" + std::to_string(levels), "", builder.take(), true, Vec3(0.1f, -0.2f, 0.05f)};
    return s;
}

TestScene triangleSoup(int count, uint64_t seed) {
    SceneBuilder builder;
    Pcg32 rng(seed, 7);
    for (int i = 0; i < count; ++i) {
        Vec3 centre(rng.uniform(), rng.uniform(), rng.uniform());
        float size = uniform(rng, 0.01f, 0.2f);
        auto corner = [&] { return centre + size * Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)); };
        Vec3 a = corner(), b = corner(), c = corner();
        builder.addTriangle(a, b, c);
    }
    for (int i = 0; i < 8; ++i) builder.addSphere({rng.uniform(), rng.uniform(), rng.uniform()}, uniform(rng, 0.02f, 0.1f));
    return TestScene{"soup-" + std::to_string(count), "", builder.take(), false, Vec3(0.0f)};
}

TestScene cornellBox() {
    SceneBuilder builder;
    // The room: five walls of two triangles each, on the planes 0 and 4 (open towards -z).
    std::vector<Vec3> room = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {4, 4, 0}, {0, 0, 4}, {4, 0, 4}, {0, 4, 4}, {4, 4, 4}};
    builder.addMesh(room, {{0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2},
                           {1, 3, 7}, {1, 7, 5}, {4, 5, 7}, {4, 7, 6}});
    addBox(builder, {0.5f, 0.0f, 1.0f}, {1.5f, 2.0f, 2.0f});
    addBox(builder, {2.25f, 0.0f, 2.5f}, {3.25f, 1.0f, 3.5f});
    builder.addSphere({3.0f, 0.5f, 1.0f}, 0.5f);
    builder.addSphere({1.0f, 2.5f, 1.5f}, 0.5f);
    return TestScene{"cornell-box", "", builder.take(), false, Vec3(0.0f)};
}

TestScene flatScene() {
    SceneBuilder builder;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            Vec3 a(0.25f * x, 0.25f * y, 0.0f);
            builder.addTriangle(a, a + Vec3(0.25f, 0, 0), a + Vec3(0.25f, 0.25f, 0));
            builder.addTriangle(a, a + Vec3(0.25f, 0.25f, 0), a + Vec3(0, 0.25f, 0));
        }
    return TestScene{"flat", "", builder.take(), false, Vec3(0.0f)};
}

TestScene bunnyOrStandIn(const std::string& modelsDir) {
    std::string path = modelsDir + "/bunny.gltf";
    std::string why;
    if (std::filesystem::exists(path)) {
        try {
            Scene scene = loadGltf(path);
            return TestScene{"bunny", "", std::move(scene), false, Vec3(0.0f)};
        } catch (const std::exception& e) {
            why = e.what();
        }
    } else {
        why = path + " does not exist (run make models)";
    }
    // A closed, bumpy sphere of 5120 triangles with bunny-like triangle counts per leaf.
    IndexedMesh mesh = icosphereMesh(4);
    for (Vec3& p : mesh.positions)
        p *= 1.0f + 0.15f * std::sin(7.0f * p.x) * std::sin(5.0f * p.y + 1.0f) * std::sin(3.0f * p.z + 2.0f);
    SceneBuilder builder;
    builder.addMesh(mesh.positions, mesh.triangles);
    return TestScene{"blob", "graded on a procedural closed mesh instead of the bunny: " + why, builder.take(), true,
                     Vec3(0.05f, 0.02f, -0.03f)};
}

TestScene teapotInAStadium(const std::string& modelsDir) {
    TestScene small = bunnyOrStandIn(modelsDir);
    std::string note = "the " + small.id + " scaled to size 1 inside a closed box of side 200";
    if (!small.note.empty()) note += "; " + small.note;
    // Its own id around the stand-in, so the reference entries of the two never mix.
    std::string id = small.id == "bunny" ? "stadium" : "stadium-" + small.id;
    return TestScene{id, note, sceneFromMesh(rtlab::teapotInAStadium(small.scene), "stadium"), true, Vec3(50.0f, 50.0f, 50.0f)};
}

std::vector<TestScene> hitSetScenes(const std::string& modelsDir) {
    std::vector<TestScene> scenes;
    scenes.push_back(icosphere(2));
    scenes.push_back(triangleSoup(2000, 1));
    scenes.push_back(cornellBox());
    scenes.push_back(bunnyOrStandIn(modelsDir));
    return scenes;
}

}  // namespace rtlab::grader
