#include "bench/bench_scenes.h"

#include "framework/core/error.h"
#include "framework/scene/benchmark_scenes.h"
#include "framework/scene/gltf_loader.h"

#include <filesystem>

namespace rtlab::bench {

namespace {
constexpr const char* kEnginePath = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
}

const std::vector<std::string>& defaultSceneNames() {
    static const std::vector<std::string> names{"bunny", "engine", "sphereflake"};
    return names;
}

Scene loadBenchScene(const std::string& name, const std::string& modelsDir) {
    if (name == "bunny") {
        std::string path = modelsDir + "/bunny.gltf";
        if (!std::filesystem::exists(path))
            throw Error(path + ": not found (run scripts/fetch-models " + modelsDir + ")");
        return loadGltf(path);
    }
    if (name == "engine") {
        if (!std::filesystem::exists(kEnginePath))
            throw Error(std::string(kEnginePath) + ": not found (install the Debian package assimp-testmodels)");
        return loadGltf(kEnginePath);
    }
    if (name == "stadium") return sceneFromMesh(teapotInAStadium(loadBenchScene("bunny", modelsDir)), "stadium");
    return loadOrGenerateScene(name);
}

Bounds3f benchRayBounds(const std::string& name, const Scene& scene) {
    if (name != "stadium") return scene.bounds();
    // The rays aim at the model, as they would without the stadium; the walls come last.
    Bounds3f model;
    for (uint32_t prim = 0; prim + kStadiumWallTriangles < scene.triangleCount(); ++prim) model.extend(scene.primitiveBounds(prim));
    return model;
}

}  // namespace rtlab::bench
