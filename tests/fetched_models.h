// The real models scripts/fetch-models puts in the build folder (bunny.gltf, engine.glb), for
// the tests that run on them. A missing model fails the test with the command that fetches it.
#pragma once

#include "framework/scene/gltf_loader.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

namespace rtlab {

inline std::string fetchedModelPath(const char* file) {
    std::string path = std::string(RTLAB_BINARY_DIR) + "/models/" + file;
    REQUIRE_MESSAGE(std::filesystem::exists(path),
                    path << " is missing: run scripts/fetch-models " << RTLAB_BINARY_DIR << "/models");
    return path;
}

inline Scene loadFetchedModel(const char* file) { return loadGltf(fetchedModelPath(file)); }

}  // namespace rtlab
