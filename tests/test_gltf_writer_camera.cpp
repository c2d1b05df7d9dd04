// The camera writeGltf emits must be valid glTF: tinygltf always writes zfar, and glTF requires
// zfar > znear (0, tinygltf's "infinite", is rejected by gltf-validator). rtlab ignores zfar, so
// it must lie beyond everything in the scene for other tools to show it all.
#include "framework/scene/gltf_loader.h"
#include "framework/scene/gltf_writer.h"

#include <doctest/doctest.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <string>

using namespace rtlab;

TEST_CASE("glTF writer: the perspective camera's zfar lies beyond the whole scene") {
    Scene scene = loadGltf(std::string(RTLAB_SOURCE_DIR) + "/scenes/cornell-box.gltf");
    std::filesystem::path directory = std::filesystem::path(RTLAB_BINARY_DIR) / "tests" / "gltf-writer-camera";
    std::filesystem::create_directories(directory);
    for (const char* name : {"cornell-box.gltf", "cornell-box.glb"}) {
        CAPTURE(name);
        std::string path = (directory / name).string();
        writeGltf(scene, path);

        tinygltf::TinyGLTF parser;
        tinygltf::Model model;
        std::string error, warning;
        bool binary = std::string(name).ends_with(".glb");
        REQUIRE((binary ? parser.LoadBinaryFromFile(&model, &error, &warning, path)
                        : parser.LoadASCIIFromFile(&model, &error, &warning, path)));
        REQUIRE(model.cameras.size() == 1);
        const tinygltf::PerspectiveCamera& camera = model.cameras[0].perspective;
        CHECK(camera.znear > 0.0);
        CHECK(camera.zfar > camera.znear);
        // The box spans (-1, 0, -1)-(1, 2, 1) or so; the camera stands in front of it.
        Bounds3f bounds = scene.bounds();
        const DVec3& eye = scene.cameras[0].position;
        for (int corner = 0; corner < 8; ++corner) {
            DVec3 p(bounds[corner & 1].x, bounds[(corner >> 1) & 1].y, bounds[(corner >> 2) & 1].z);
            CHECK(glm::length(p - eye) < camera.zfar);
        }
    }
}
