// rtlab view SCENE [--accel NAME] [--ray "ox oy oz dx dy dz" | --rays FILE --index K | --pixel X,Y] -o DIR
// rtlab view --samplers -o DIR
// The viewer (docs/viewer.md): a folder whose index.html shows the structure, a ray's way through
// it step by step against the reference's, a render with its cost heat map, or a6's samplers and
// estimators. The work is in viewer/; this file parses the command and hands the viewer the
// assignment functions it calls (the DDA, the samplers, the estimators) as function objects.
#include "cli/commands.h"
#include "cli/this_build.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/core/error.h"
#include "framework/core/ray_file.h"
#include "framework/interface/a3_grid.h"
#include "framework/interface/a6_radiometry.h"
#include "grader/a6_radiometry/wire/sample_calls.h"
#include "viewer/radiometry_panels.h"
#include "viewer/scene_case.h"
#include "viewer/viewer_folder.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace rtlab::cli {
namespace {

namespace fs = std::filesystem;
using grader::worker::Estimator;
using grader::worker::Sampler;

struct ViewOptions {
    std::string scenePath;
    std::string accelerator = AcceleratorSpec().name;
    std::string ray;
    std::string raysPath;
    long index = -1;
    std::string pixel;
    int width = 0, height = 0;
    std::string camera;
    bool samplers = false;
    bool noReference = false;
    std::string outputDir;
    // The reference's side, when rtlab runs rtlab-solution: traces only, no viewer.
    std::string traceOut;
    size_t anyHitFrom = std::numeric_limits<size_t>::max();
};

Ray parseRay(const std::string& text) {
    std::istringstream in(text);
    std::vector<float> v;
    std::string token;
    while (in >> token) {
        float x = 0.0f;
        auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
        if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(x))
            throw Error("--ray: '" + token + "' is not a finite number (expected \"ox oy oz dx dy dz\")");
        v.push_back(x);
    }
    if (v.size() != 6) throw Error("--ray: " + std::to_string(v.size()) + " numbers, expected 6 (\"ox oy oz dx dy dz\")");
    Ray ray;
    ray.origin = Vec3(v[0], v[1], v[2]);
    ray.direction = Vec3(v[3], v[4], v[5]);
    if (ray.direction == Vec3(0.0f)) throw Error("--ray: the direction is zero");
    return ray;
}

std::array<int, 2> parsePixel(const std::string& text) {
    int x = -1, y = -1;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &rest) != 2 || x < 0 || y < 0)
        throw Error("--pixel '" + text + "': expected X,Y, two whole numbers from 0 (the top-left pixel is 0,0)");
    return {x, y};
}

// rtlab-solution beside this executable, when this is not it: it traces the same rays.
fs::path referenceProgram() {
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec || self.filename() == "rtlab-solution") return {};
    fs::path solution = self.parent_path() / "rtlab-solution";
    return fs::is_regular_file(solution) ? solution : fs::path();
}

// The a3 DDA this executable links, as the viewer calls it.
std::vector<GridCell> linkedDdaWalk(const UniformGrid& grid, const Ray& ray, float tEnter, float tExit, size_t maxCells) {
    DdaState state = ddaSetup(grid, ray, tEnter, tExit);
    std::vector<GridCell> cells = {state.cell};
    while (cells.size() < maxCells && ddaStep(state, grid.resolution)) cells.push_back(state.cell);
    return cells;
}

Vec3 linkedSampler(const grader::worker::SamplerCall& c, Vec2 u) { return grader::worker::sampleOnce(c, u).value; }

void view(const ViewOptions& o) {
    auto start = std::chrono::steady_clock::now();
    int modes = !o.ray.empty() + !o.raysPath.empty() + !o.pixel.empty();
    if (modes > 1) throw Error("view: give one of --ray, --rays with --index, and --pixel");
    if (o.index >= 0 && o.raysPath.empty()) throw Error("view: --index needs --rays FILE");
    if (!o.traceOut.empty()) {
        // The reference's side of a view: every ray of the file, traced into traceOut.
        if (o.raysPath.empty() || o.scenePath.empty()) throw Error("view --trace-out needs SCENE and --rays");
        std::vector<Ray> rays = readRayFile(o.raysPath);
        viewer::writeRayTraces(o.scenePath, o.accelerator, rays, std::min(o.anyHitFrom, rays.size()), o.traceOut);
        return;
    }
    if (o.outputDir.empty()) throw Error("view: -o DIR is required (the folder to write index.html into)");
    viewer::checkViewerTarget(o.outputDir);  // before any work

    if (o.samplers) {
        if (!o.scenePath.empty() || modes > 0) throw Error("view --samplers takes no scene and no ray");
        viewer::CaseView page;
        page.title = "a6: samplers and estimators";
        page.samplers = viewer::samplerPanels(linkedSampler);
        page.estimators = viewer::estimatorCurves(grader::worker::estimateSample);
        viewer::writeCaseViewer(o.outputDir, page);
        std::printf("wrote %s/index.html: %zu samplers, %zu estimators\n", o.outputDir.c_str(), page.samplers.size(), page.estimators.size());
        return;
    }
    if (o.scenePath.empty()) throw Error("view: give a SCENE (or --samplers for a6)");
    acceleratorTypeOf(o.accelerator);  // an unknown --accel fails here, before the scene is loaded

    viewer::SceneCaseRequest request;
    request.scenePath = o.scenePath;
    request.acceleratorName = o.accelerator;
    request.width = o.width;
    request.height = o.height;
    request.cameraName = o.camera;
    request.repositoryDir = repositoryDir();
    if (!o.noReference) request.referenceProgram = referenceProgram();
    request.ddaWalk = linkedDdaWalk;
    if (!o.ray.empty()) {
        request.rays = {parseRay(o.ray)};
        request.rayLabel = "the ray of --ray";
    } else if (!o.raysPath.empty()) {
        std::vector<Ray> rays = readRayFile(o.raysPath);
        if (o.index < 0) throw Error("view: --rays needs --index K (which ray of " + o.raysPath + " to show)");
        if (static_cast<size_t>(o.index) >= rays.size())
            throw Error(o.raysPath + ": ray index " + std::to_string(o.index) + " is out of range (the file has " + std::to_string(rays.size()) +
                        " rays, 0.." + std::to_string(rays.size() == 0 ? 0 : rays.size() - 1) + ")");
        request.rays = {rays[o.index]};
        request.rayLabel = "ray " + std::to_string(o.index) + " of " + fs::path(o.raysPath).filename().string();
    } else if (!o.pixel.empty()) {
        request.pixel = parsePixel(o.pixel);
        request.pixelCommand = "rtlab view " + o.scenePath + " --accel " + o.accelerator + " --pixel X,Y -o " + o.outputDir + "-X-Y";
    }
    viewer::SceneCase built = viewer::buildSceneCase(request);
    viewer::writeCaseViewer(o.outputDir, built.view);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The time beyond loading and building is what the viewer costs (docs/viewer.md#scale).
    std::printf("wrote %s/index.html: %s with %s, %zu ray%s, in %.2f s (scene %.2f s, build %.2f s, the rest %.2f s)\n", o.outputDir.c_str(),
                fs::path(o.scenePath).filename().c_str(), o.accelerator.c_str(), built.view.rays.size(), built.view.rays.size() == 1 ? "" : "s",
                seconds, built.loadSeconds, built.buildSeconds, seconds - built.loadSeconds - built.buildSeconds);
}

}  // namespace

void addViewCommand(CLI::App& app) {
    auto options = std::make_shared<ViewOptions>();
    CLI::App* command = app.add_subcommand(
        "view", "Write a viewer folder (index.html, opens from file://): a structure, a ray's way through it against the reference's, "
                "a pixel's rays, or a6's samplers (docs/viewer.md)");
    command->add_option("scene", options->scenePath, "glTF 2.0 scene (.gltf or .glb)")->check(CLI::ExistingFile);
    command->add_option("--accel", options->accelerator, "Accelerator, one of:\n" + acceleratorNames())->capture_default_str();
    command->add_option("--ray", options->ray, "One ray: \"ox oy oz dx dy dz\"");
    command->add_option("--rays", options->raysPath, "Ray file (the format of rtlab hits), with --index")->check(CLI::ExistingFile);
    command->add_option("--index", options->index, "Which ray of --rays to show (from 0)")->check(CLI::NonNegativeNumber);
    command->add_option("--pixel", options->pixel, "X,Y: render the scene and show this pixel's camera ray and shadow rays");
    command->add_option("--width", options->width, "Image width with --pixel (default: the reference's, else 320)")->check(CLI::Range(1, 1 << 13));
    command->add_option("--height", options->height, "Image height with --pixel")->check(CLI::Range(1, 1 << 13));
    command->add_option("--camera", options->camera, "Camera by name with --pixel (default: the first)");
    command->add_flag("--samplers", options->samplers, "a6: the samplers' points and histograms, the estimators' errors (no scene)");
    command->add_flag("--no-reference", options->noReference, "Do not run rtlab-solution for the reference's traces");
    command->add_option("-o,--output", options->outputDir, "Folder to write (new, empty, or a viewer written before)");
    // The reference's side of a view (rtlab runs rtlab-solution with these): not for people.
    command->add_option("--trace-out", options->traceOut)->group("");
    command->add_option("--any-hit-from", options->anyHitFrom)->group("");
    command->callback([options] { view(*options); });
}

}  // namespace rtlab::cli
