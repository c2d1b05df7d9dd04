// Where the framework's tests write their files: folders under build/test-output, one a test
// file, kept after the run so that a failing case's images can be looked at.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>

namespace rtlab::test {

// build/test-output/NAME, created if missing.
inline std::filesystem::path outputDir(const std::string& name) {
    std::filesystem::path dir = std::filesystem::path(RTLAB_BINARY_DIR) / "test-output" / name;
    std::filesystem::create_directories(dir);
    return dir;
}

// build/test-output/NAME/scenes, emptied, holding copies of the committed scenes named by their
// paths under scenes/ ("light-behind.gltf", "radiometry/closed-form.gltf"): a scene folder
// that `rtlab refs --scenes` may write references into.
inline std::filesystem::path scratchScenes(const std::string& name, std::initializer_list<std::string> scenes) {
    namespace fs = std::filesystem;
    fs::path root = fs::path(RTLAB_BINARY_DIR) / "test-output" / name;
    fs::remove_all(root);
    for (const std::string& scene : scenes) {
        fs::path copy = root / "scenes" / scene;
        fs::create_directories(copy.parent_path());
        fs::copy_file(fs::path(RTLAB_SOURCE_DIR) / "scenes" / scene, copy);
    }
    return root / "scenes";
}

}  // namespace rtlab::test
