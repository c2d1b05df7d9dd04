// rtlab scene generate|rays|checksums: the procedural benchmark scenes and the benchmark ray
// sets of docs/performance.md#what-is-measured, and their FNV-1a fingerprints.
#include "cli/commands.h"
#include "framework/core/error.h"
#include "framework/scene/benchmark_rays.h"
#include "framework/scene/benchmark_scenes.h"
#include "framework/scene/gltf_loader.h"
#include "framework/scene/gltf_writer.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace rtlab::cli {
namespace {

constexpr const char* kStadium = "stadium";

std::string hex(uint64_t value) {
    std::ostringstream out;
    out << std::hex << std::setw(16) << std::setfill('0') << value;
    return out.str();
}

struct GenerateOptions {
    std::string name;
    std::string outputPath;
    std::string modelPath;  // the stadium's model
};

void generate(const GenerateOptions& options) {
    if ((options.name == kStadium) != !options.modelPath.empty())
        throw Error(options.name == kStadium ? "scene generate stadium needs --model FILE (the model to put in the stadium)"
                                             : "--model is for scene generate stadium only");
    Scene scene = options.name == kStadium ? makeStadiumScene(loadGltf(options.modelPath)) : makeGeneratedScene(options.name);
    writeGltf(scene, options.outputPath);
    std::cout << options.name << ": " << scene.triangleCount() << " triangles, checksum "
              << hex(triangleChecksum(scene)) << ", written to " << options.outputPath << "\n";
}

struct RaysOptions {
    std::string scene;
    std::string kind = "primary";
    std::string outputPath;
    uint32_t count = 0;  // 0 = the whole set
};

// The rays as text, one per line (`ox oy oz dx dy dz`, the format of rtlab hits --rays), with
// 9 significant digits so every float reads back exactly. --count N keeps N rays spread evenly
// over the set (ray i * size / N), so a subset sees the whole image or the whole stream.
void writeRays(const RaysOptions& options) {
    RayKind kind = parseRayKind(options.kind);
    Scene scene = loadOrGenerateScene(options.scene);
    std::vector<Ray> rays = makeBenchmarkRays(kind, scene.bounds());
    uint64_t checksum = rayChecksum(rays);
    size_t count = options.count == 0 ? rays.size() : std::min<size_t>(options.count, rays.size());

    std::ofstream out(options.outputPath);
    if (!out) throw Error(options.outputPath + ": cannot open for writing");
    out << std::setprecision(std::numeric_limits<float>::max_digits10);
    for (size_t i = 0; i < count; ++i) {
        const Ray& ray = rays[i * rays.size() / count];
        out << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z << ' ' << ray.direction.x << ' '
            << ray.direction.y << ' ' << ray.direction.z << '\n';
    }
    if (!out.flush()) throw Error(options.outputPath + ": write failed");
    std::cout << count << " of " << rays.size() << " " << options.kind << " rays (set checksum "
              << hex(checksum) << ") written to " << options.outputPath << "\n";
}

void printChecksums(const std::string& nameOrPath) {
    Scene scene = loadOrGenerateScene(nameOrPath);
    Bounds3f bounds = scene.bounds();
    std::cout << std::setprecision(std::numeric_limits<float>::max_digits10);
    std::cout << "scene       " << scene.sourcePath << "\n"
              << "triangles   " << scene.triangleCount() << "  checksum " << hex(triangleChecksum(scene)) << "\n"
              << "bounds      (" << bounds.lower.x << ", " << bounds.lower.y << ", " << bounds.lower.z << ") - ("
              << bounds.upper.x << ", " << bounds.upper.y << ", " << bounds.upper.z << ")\n";
    for (RayKind kind : {RayKind::Primary, RayKind::Incoherent})
        std::cout << std::left << std::setw(12) << rayKindName(kind) << hex(rayChecksum(makeBenchmarkRays(kind, bounds)))
                  << "\n";
}

}  // namespace

void addSceneCommand(CLI::App& app) {
    CLI::App* scene = app.add_subcommand(
        "scene", "Benchmark scenes and ray sets (docs/performance.md#what-is-measured)");
    scene->require_subcommand(1);

    auto generateOptions = std::make_shared<GenerateOptions>();
    CLI::App* generateCommand = scene->add_subcommand(
        "generate", "Write a procedural benchmark scene as glTF, with a camera and a light so it renders");
    std::vector<std::string> names = generatedSceneNames();
    names.push_back(kStadium);
    generateCommand
        ->add_option("name", generateOptions->name,
                     "sphereflake (1,062,864 triangles), randsoup (2^20), or stadium (--model in a box of side 200)")
        ->required()
        ->check(CLI::IsMember(names));
    generateCommand->add_option("--model", generateOptions->modelPath,
                                "stadium: the glTF model to scale to size 1 and put at the centre (e.g. build/models/bunny.gltf)");
    generateCommand->add_option("-o,--output", generateOptions->outputPath, "Output file (.glb binary, else .gltf)")
        ->required();
    generateCommand->callback([generateOptions] { generate(*generateOptions); });

    auto raysOptions = std::make_shared<RaysOptions>();
    CLI::App* raysCommand =
        scene->add_subcommand("rays", "Write a benchmark ray set as text (the format of rtlab hits --rays)");
    raysCommand->add_option("scene", raysOptions->scene, "glTF file, or sphereflake / randsoup")->required();
    raysCommand->add_option("--kind", raysOptions->kind, "primary (1024x1024 camera rays) or incoherent (2^20)")
        ->check(CLI::IsMember({"primary", "incoherent"}));
    raysCommand->add_option("-o,--output", raysOptions->outputPath, "Output text file")->required();
    raysCommand->add_option("--count", raysOptions->count, "Keep N rays spread evenly over the set (default: all)");
    raysCommand->callback([raysOptions] { writeRays(*raysOptions); });

    auto checksumScene = std::make_shared<std::string>();
    CLI::App* checksumsCommand = scene->add_subcommand(
        "checksums", "Print triangle count, bounds and the FNV-1a 64 checksums of a scene and its ray sets");
    checksumsCommand->add_option("scene", *checksumScene, "glTF file, or sphereflake / randsoup")->required();
    checksumsCommand->callback([checksumScene] { printChecksums(*checksumScene); });
}

}  // namespace rtlab::cli
