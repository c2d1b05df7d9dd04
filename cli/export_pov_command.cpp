// rtlab export-pov SCENE -o scene.pov [--width W --height H] [--camera NAME]: the scene as a
// POV-Ray 3.7 file that renders what `rtlab render` renders (framework/pov/pov_exporter.h).
#include "cli/commands.h"
#include "framework/core/error.h"
#include "framework/pov/pov_exporter.h"
#include "framework/pov/pov_reference.h"
#include "framework/scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>

namespace rtlab::cli {
namespace {

struct ExportPovOptions {
    std::string scenePath;
    std::string outputPath;
    std::string cameraName;
    int width = 320;
    int height = 240;
};

void exportPov(const ExportPovOptions& options) {
    Scene scene = loadGltf(options.scenePath);
    const Camera& camera = scene.camera(options.cameraName);
    std::string text = exportPovScene(scene, camera, options.width, options.height);
    std::ofstream out(options.outputPath);
    out << text;
    out.close();
    if (!out) throw Error(options.outputPath + ": cannot write the POV-Ray scene");
    std::cout << "wrote " << options.outputPath << "; render it with:\n  povray -i" << options.outputPath << " "
              << povReferenceSettings(options.width, options.height) << " -Oimage.png\n";
}

}  // namespace

void addExportPovCommand(CLI::App& app) {
    auto options = std::make_shared<ExportPovOptions>();
    CLI::App* command = app.add_subcommand(
        "export-pov", "Write a glTF scene as a POV-Ray 3.7 scene that renders the same image (docs/verification.md)");
    command->add_option("scene", options->scenePath, "glTF 2.0 scene (.gltf or .glb)")->required();
    command->add_option("-o,--output", options->outputPath, "The .pov file to write")->required();
    command->add_option("--camera", options->cameraName, "Camera by name (default: the first)");
    command->add_option("--width", options->width, "Image width the render command in the file's header uses")
        ->capture_default_str()
        ->check(CLI::Range(1, 65536));
    command->add_option("--height", options->height, "Image height the render command in the file's header uses")
        ->capture_default_str()
        ->check(CLI::Range(1, 65536));
    command->callback([options] { exportPov(*options); });
}

}  // namespace rtlab::cli
