// rtlab export-blender SCENE -o scene.py [--camera NAME] [--width W --height H] [--samples N]
// [--seed S] [--emitter-edge L]: the scene as a Blender 3.4 Python script that builds it
// natively and renders, with Cycles, the radiance `rtlab render` computes
// (framework/blender/blender_exporter.h).
#include "cli/commands.h"
#include "framework/blender/blender_exporter.h"
#include "framework/core/error.h"
#include "framework/scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>

namespace rtlab::cli {
namespace {

struct ExportBlenderOptions {
    std::string scenePath;
    std::string outputPath;
    std::string cameraName;
    BlenderSettings settings;
};

void exportBlender(const ExportBlenderOptions& options) {
    Scene scene = loadGltf(options.scenePath);
    const Camera& camera = scene.camera(options.cameraName);
    std::string text = exportBlenderScene(scene, camera, options.settings);
    std::ofstream out(options.outputPath);
    out << text;
    out.close();
    if (!out) throw Error(options.outputPath + ": cannot write the Blender script");
    std::cout << "wrote " << options.outputPath << "; render it with:\n  blender -b --factory-startup --python-exit-code 1 -P "
              << options.outputPath << " -- image.exr\n";
}

}  // namespace

void addExportBlenderCommand(CLI::App& app) {
    auto options = std::make_shared<ExportBlenderOptions>();
    CLI::App* command = app.add_subcommand(
        "export-blender",
        "Write a glTF scene as a Blender 3.4 script that renders, with Cycles, the radiance rtlab renders "
        "(docs/verification.md#6-blender-cycles-references)");
    command->add_option("scene", options->scenePath, "glTF 2.0 scene (.gltf or .glb)")->required();
    command->add_option("-o,--output", options->outputPath, "The .py file to write")->required();
    command->add_option("--camera", options->cameraName, "Camera by name (default: the first)");
    BlenderSettings& s = options->settings;
    command->add_option("--width", s.width, "Image width")->capture_default_str()->check(CLI::Range(1, 65536));
    command->add_option("--height", s.height, "Image height")->capture_default_str()->check(CLI::Range(1, 65536));
    command->add_option("--samples", s.samples, "Cycles samples per pixel")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 24));
    command->add_option("--seed", s.seed, "Cycles seed (the same seed renders the same image)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1 << 30));
    command->add_option("--emitter-edge", s.emitterEdge,
                        "Cut emissive triangles until no edge is longer than this (scene units): Cycles samples "
                        "larger ones by a biased path")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    command->callback([options] { exportBlender(*options); });
}

}  // namespace rtlab::cli
