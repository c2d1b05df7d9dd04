#include "framework/blender/blender_reference.h"

#include "framework/core/error.h"

#include <chrono>
#include <fstream>

namespace rtlab {
namespace fs = std::filesystem;

double renderBlenderReference(const Scene& scene, const Camera& camera, const BlenderSettings& settings,
                              const fs::path& outputExr, double timeLimitSeconds) {
    std::string script = exportBlenderScene(scene, camera, settings);
    TemporaryDirectory work("rtlab-blender");
    {
        std::ofstream out(work.path() / "scene.py");
        out << script;
        if (!out) throw Error((work.path() / "scene.py").string() + ": cannot write the Blender script");
    }
    auto start = std::chrono::steady_clock::now();
    // Absolute paths: Blender resolves relative ones against $PWD, not its working folder.
    fs::path image = work.path() / "image.exr";
    runBlenderOrThrow({"-P", (work.path() / "scene.py").string(), "--", image.string()}, work,
                      "rendering " + scene.sourcePath, timeLimitSeconds);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::error_code error;
    fs::copy_file(image, outputExr, fs::copy_options::overwrite_existing, error);
    if (error) throw Error(outputExr.string() + ": cannot write the Blender reference: " + error.message());
    return seconds;
}

}  // namespace rtlab
