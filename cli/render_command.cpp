// rtlab render SCENE -o OUT: renders a glTF scene with the chosen accelerator
// (docs/rendering.md) and prints one summary line: time, throughput, work per ray.
#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "cli/accelerator_options.h"
#include "cli/commands.h"
#include "cli/render_accelerator.h"
#include "framework/render/light_sampling.h"
#include "framework/core/error.h"
#include "framework/render/image_io.h"
#include "framework/render/renderer.h"
#include "framework/verification/trace_share.h"
#include "framework/render/tiles.h"
#include "framework/scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace rtlab::cli {
namespace {

namespace fs = std::filesystem;

// The size of the POV-Ray references in scenes/refs (320x240 with the scenes' 4:3 cameras), so
// a default render can be compared with its reference as it is.
constexpr int kDefaultWidth = 320;
constexpr double kDefaultAspect = 4.0 / 3.0;  // when the camera does not give one

struct RenderOptions {
    std::string scenePath;
    std::string outputPath;
    int width = 0;   // 0 = derived
    int height = 0;  // 0 = derived
    std::string cameraName;
    AcceleratorSpec accelerator;
    bool acceleratorGiven = false;  // --accel on the command line
    int threads = 0;
    bool srgb8 = false;     // kept for scripts: 8-bit sRGB is the PNG default
    bool linear16 = false;  // 16-bit linear PNG, the format of the references
    float exposure = 0.0f;
    std::vector<std::string> aovNames;
    std::string aovDir;
    int samplesPerPixel = 1;
    uint64_t seed = 0;
    std::string lightSampling = lightSamplingName(RenderSettings().lightSampling);
    bool timings = false;
};

// How many renders and replays --timings takes the best of.
constexpr int kTimingRepeats = 9;

// A missing side follows from the other and the camera's aspect ratio.
void resolveImageSize(RenderOptions& options, const Camera& camera) {
    double aspect = camera.aspectRatio > 0.0 ? camera.aspectRatio : kDefaultAspect;
    if (options.width == 0 && options.height == 0) options.width = kDefaultWidth;
    if (options.width == 0) options.width = std::max(1, static_cast<int>(std::lround(options.height * aspect)));
    if (options.height == 0) options.height = std::max(1, static_cast<int>(std::lround(options.width / aspect)));
}

// OUT.png with AOV "depth" becomes AOVDIR/OUT.depth.png.
std::string aovPath(const RenderOptions& options, Aov aov) {
    fs::path output(options.outputPath);
    fs::path dir = options.aovDir.empty() ? output.parent_path() : fs::path(options.aovDir);
    return (dir / (output.stem().string() + "." + aovName(aov) + output.extension().string())).string();
}

void refuseToOverwriteScene(const std::string& path, const std::string& scenePath) {
    std::error_code ignored;
    if (fs::equivalent(path, scenePath, ignored))
        throw Error(path + ": refusing to overwrite the input scene");
}

void render(RenderOptions options) {
    std::vector<Aov> aovs;
    for (const std::string& name : options.aovNames) aovs.push_back(parseAov(name));
    LightSampling lightSampling = parseLightSampling(options.lightSampling);
    if (options.srgb8 && options.linear16) throw Error(options.outputPath + ": --srgb8 and --linear16 exclude each other");
    // A PNG is for looking at unless --linear16 asks for the references' format; .exr stays linear.
    std::string outputExtension = fs::path(options.outputPath).extension().string();
    bool png = outputExtension == ".png" || outputExtension == ".PNG";
    ImageWriteOptions writeOptions{options.srgb8 || (png && !options.linear16), options.exposure};
    // Fail on bad outputs before the work, not after it.
    checkImageOutput(options.outputPath, writeOptions);
    if (options.linear16 && !png) throw Error(options.outputPath + ": --linear16 needs a .png file (.exr is always linear)");
    refuseToOverwriteScene(options.outputPath, options.scenePath);
    for (Aov aov : aovs) {
        checkImageOutput(aovPath(options, aov));
        refuseToOverwriteScene(aovPath(options, aov), options.scenePath);
    }
    chooseAccelerator(options.accelerator);  // an unknown --accel fails here, before the scene is loaded

    Scene scene = loadGltf(options.scenePath);
    const Camera& camera = scene.camera(options.cameraName);
    resolveImageSize(options, camera);

    auto buildStart = std::chrono::steady_clock::now();
    PrimitiveSet primitives(scene);
    std::unique_ptr<Accelerator> accelerator = buildRenderAccelerator(options.accelerator, options.acceleratorGiven, primitives,
                                                                      makeAccelerator, std::cerr);
    double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();

    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.threads = options.threads;
    settings.aovs = aovs;
    settings.samplesPerPixel = options.samplesPerPixel;
    settings.seed = options.seed;
    settings.lightSampling = lightSampling;
    // fast/'s structures skip the camera rays that cannot reach the scene; a student's is asked every ray.
    settings.cullOutsideBounds = chooseAccelerator(options.accelerator).type->speedRank > 0;
    RenderResult result = Renderer(scene, camera, *accelerator).render(settings);

    writeImage(options.outputPath, result.colour, writeOptions);
    std::string extension = fs::path(options.outputPath).extension().string();
    bool integerFiles = !(extension == ".exr" || extension == ".EXR");
    for (Aov aov : aovs)
        writeImage(aovPath(options, aov), aovImage(aov, result.aovs, options.width, options.height, integerFiles));

    TraversalStats total = result.primary;
    total += result.shadow;
    double rays = static_cast<double>(std::max<uint64_t>(total.rays, 1));
    std::printf("rendered %dx%d at %d spp with %s on %d threads in %.3f s (build %.3f s): %.2f Mrays/s, "
                "%llu camera + %llu shadow rays",
                options.width, options.height, options.samplesPerPixel, options.accelerator.name.c_str(),
                resolveThreadCount(options.threads), result.seconds, buildSeconds,
                total.rays / std::max(result.seconds, 1e-9) / 1e6,
                static_cast<unsigned long long>(result.primary.rays),
                static_cast<unsigned long long>(result.shadow.rays));
    if (result.culledRays > 0)
        std::printf(" (%llu camera rays more not traced: outside the scene's bounds)", static_cast<unsigned long long>(result.culledRays));
    std::printf(", per ray %.1f node visits", total.nodeVisits / rays);
    // The steps only structures that take them have: a grid's cells, a KD-tree's planes.
    if (total.cellSteps > 0) std::printf(", %.1f cell steps", total.cellSteps / rays);
    if (total.planeSteps > 0) std::printf(", %.1f plane steps", total.planeSteps / rays);
    std::printf(" and %.1f primitive tests", total.primitiveTests / rays);
    if (!result.aovs.cost.empty()) std::printf("; cost AOV max %u", maxCount(result.aovs.cost));
    if (!result.aovs.steps.empty()) std::printf("; steps AOV max %u", maxCount(result.aovs.steps));
    std::printf("\n");
    if (options.timings) {
        TraceShare share = measureTraceShare(scene, camera, *accelerator, settings, kTimingRepeats);
        std::printf("timings (best of %d): render %.3f s, its %zu queries traced alone %.3f s, beyond tracing %.1f %% "
                    "(median of the %d passes' own shares %.1f %%)\n",
                    kTimingRepeats, share.renderSeconds, share.queries, share.traceSeconds, 100.0 * share.beyondTracing(),
                    kTimingRepeats, 100.0 * share.pairedBeyondTracing());
    }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand("render", "Render a glTF scene to EXR or PNG (docs/rendering.md)");
    command->add_option("scene", options->scenePath, "glTF 2.0 scene (.gltf or .glb)")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", options->outputPath,
                        "Image to write: .exr (linear float32) or .png (8-bit sRGB for viewing; 16-bit linear with --linear16)")
        ->required();
    command->add_option("--width", options->width, "Image width in pixels (default 320 as the references, or from --height and the camera's aspect)")
        ->check(CLI::Range(1, 1 << 15));
    command->add_option("--height", options->height, "Image height in pixels (default from the width and the camera's aspect, else 4:3)")
        ->check(CLI::Range(1, 1 << 15));
    command->add_option("--camera", options->cameraName, "Camera by name (default: the first)");
    // With fast/ linked in (rtlab-solution), the fastest structure renders unless --accel says otherwise.
    options->accelerator.name = defaultRenderAccelerator();
    addAcceleratorOptions(command, options->accelerator, "Accelerator");
    // Whether --accel was given decides whether an a2 stub may fall back to bvh-median.
    CLI::Option* accel = command->get_option("--accel");
    command->add_option("--threads", options->threads, "Worker threads (0 = one per hardware thread)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command->add_flag("--linear16", options->linear16,
                      "Write a 16-bit linear PNG, the format of the references rtlab compare and refs read");
    command->add_flag("--srgb8", options->srgb8, "Write an 8-bit sRGB PNG for viewing (the default for .png)");
    command->add_option("--exposure", options->exposure, "8-bit sRGB PNG only: multiply by 2^EV before the sRGB curve");
    command->add_option("--aov", options->aovNames, "Also write an AOV: normal, depth, prim, cost or steps (repeatable)")
        ->check(CLI::IsMember({"normal", "depth", "prim", "cost", "steps"}))
        ->allow_extra_args(false);  // one name per --aov, so a following SCENE is not taken
    command->add_option("--aov-dir", options->aovDir, "Directory for AOV files OUT.<aov>.<ext> (default: OUT's)")
        ->check(CLI::ExistingDirectory);
    command->add_option("--spp", options->samplesPerPixel,
                        "Samples per pixel: 1 = the pixel centre (as the POV-Ray references), N = N stratified camera rays")
        ->check(CLI::Range(1, kMaxSamplesPerPixel))
        ->capture_default_str();
    command->add_option("--seed", options->seed, "Seed of the pixels' random streams (the same seed gives the same image)")
        ->capture_default_str();
    command->add_option("--light-sampling", options->lightSampling,
                        "Emissive triangles and spheres: sample a light by its area or its solid angle, or a direction "
                        "(uniform hemisphere or cosine-weighted)")
        ->check(CLI::IsMember({"area", "solid-angle", "hemisphere", "cosine"}))
        ->capture_default_str();
    command->add_flag("--timings", options->timings,
                      "Also time the render's own accelerator queries alone (best of 9 renders and 9 replays, and the median of each pair's share) and "
                      "print the share of the time spent beyond tracing");
    command->callback([options, accel] {
        options->acceleratorGiven = accel->count() > 0;
        render(*options);
    });
}

}  // namespace rtlab::cli
