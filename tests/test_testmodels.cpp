// The loader against every glTF file of the Debian package assimp-testmodels: valid models,
// glTF 1.0 files, and files broken on purpose (index out of range, infinite vertices, missing
// buffers, recursive nodes, wrong JSON types). Each must load or fail with one rtlab::Error
// line naming the file; a crash or a hang fails the whole run (CI also runs this under
// ASan/UBSan).
#include "framework/core/error.h"
#include "framework/scene/gltf_loader.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = "/usr/share/assimp/models";

std::vector<fs::path> gltfFiles() {
    std::vector<fs::path> files;
    for (const char* folder : {"glTF2", "glTF"}) {
        if (!fs::is_directory(kModels / folder)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(kModels / folder)) {
            std::string extension = entry.path().extension().string();
            if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb"))
                files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST_CASE("assimp-testmodels: every glTF file loads or fails with one line naming it") {
    std::vector<fs::path> files = gltfFiles();
    // The package ships 46 glTF2 and 7 glTF files.
    REQUIRE_MESSAGE(files.size() >= 40, "install the Debian package assimp-testmodels (scripts/install-deps)");
    int loaded = 0, rejected = 0;
    for (const fs::path& file : files) {
        CAPTURE(file.string());
        try {
            Scene scene = loadGltf(file.string());
            ++loaded;
            bool finite = std::all_of(scene.triangles.positions.begin(), scene.triangles.positions.end(),
                                      [](const Vec3& p) {
                                          return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
                                      });
            CHECK(finite);
            bool indicesInRange = std::all_of(
                scene.triangles.indices.begin(), scene.triangles.indices.end(), [&](const auto& triangle) {
                    return std::all_of(triangle.begin(), triangle.end(),
                                       [&](uint32_t v) { return v < scene.triangles.positions.size(); });
                });
            CHECK(indicesInRange);
            CHECK(scene.triangles.material.size() == scene.triangleCount());
            CHECK(scene.triangles.smooth.size() == scene.triangleCount());
        } catch (const Error& e) {
            ++rejected;
            std::string message = e.what();
            CAPTURE(message);
            CHECK(message.find(file.filename().string()) != std::string::npos);
            CHECK(message.find('\n') == std::string::npos);
        }
    }
    MESSAGE(loaded << " loaded, " << rejected << " rejected with a clear error");
    CHECK(loaded > 0);
    CHECK(rejected > 0);  // the package holds broken files on purpose
}

TEST_CASE("assimp-testmodels: 2CylinderEngine.glb matches docs/performance.md") {
    const fs::path engine = kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    REQUIRE(fs::exists(engine));
    Scene scene = loadGltf(engine.string());
    CHECK(scene.triangleCount() == 121496);
    CHECK(scene.triangles.positions.size() == 84657);
    Bounds3f bounds = scene.bounds();
    const double epsilon = 1e-5;  // the anchors give six significant digits
    CHECK(bounds.lower.x == doctest::Approx(-371.692).epsilon(epsilon));
    CHECK(bounds.lower.y == doctest::Approx(-180.972).epsilon(epsilon));
    CHECK(bounds.lower.z == doctest::Approx(-140.0).epsilon(epsilon));
    CHECK(bounds.upper.x == doctest::Approx(371.692).epsilon(epsilon));
    CHECK(bounds.upper.y == doctest::Approx(92.0416).epsilon(epsilon));
    CHECK(bounds.upper.z == doctest::Approx(128.0).epsilon(epsilon));
}
