#include "viewer/scene_case.h"

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/grid/grid_accelerator.h"
#include "framework/accel/traversal_trace_format.h"
#include "framework/core/error.h"
#include "framework/core/ray_file.h"
#include "framework/external/external_process.h"
#include "framework/oracle/oracle.h"
#include "framework/render/aov.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/render/renderer.h"
#include "framework/render/spawn_ray.h"
#include "framework/scene/gltf_loader.h"
#include "grader/a3_grid/grid_oracle.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

namespace rtlab::viewer {
namespace {

namespace fs = std::filesystem;

constexpr int kDefaultWidth = 320;  // the references' size (scenes/refs)
constexpr size_t kMaxDdaCells = 1u << 16;
constexpr double kReferenceSeconds = 120.0;

std::string describeRay(const Ray& r) {
    char text[200];
    std::snprintf(text, sizeof text, "(%g, %g, %g) towards (%g, %g, %g)", r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y,
                  r.direction.z);
    return text;
}

// A query through the accelerator with its trace. A stub the traversal meets ends the query
// with no answer; the trace keeps what happened before it.
struct TracedQuery {
    TraversalTrace trace;
    RayAnswer answer;
    std::string problem;
};

TracedQuery traceQuery(const Accelerator& accelerator, const Ray& ray, bool anyHit) {
    TracedQuery q;
    TraversalStats stats;
    stats.trace = &q.trace;
    try {
        if (anyHit) {
            q.answer = RayAnswer::anyHit(accelerator.occluded(ray, stats));
        } else {
            Hit hit = accelerator.intersect(ray, stats);
            q.answer = RayAnswer::closest(hit.prim, hit.t);
        }
    } catch (const NotImplemented& e) {
        q.problem = e.what();
    }
    return q;
}

RayAnswer oracleAnswer(const Oracle& oracle, const Ray& ray, bool anyHit) {
    if (anyHit) return RayAnswer::anyHit(oracle.anyHit(OracleRay::from(ray)));
    OracleHit hit = oracle.closestHit(OracleRay::from(ray));
    return RayAnswer::closest(hit.hit ? hit.prim : kNoHit, static_cast<float>(hit.t));
}

// Where the ray's segment runs inside box: a slab test in double, clipped to [tMin, tMax].
std::optional<std::pair<float, float>> segmentIn(const Bounds3f& box, const Ray& ray) {
    double t0 = ray.tMin, t1 = ray.tMax;
    for (int a = 0; a < 3; ++a) {
        double o = ray.origin[a], d = ray.direction[a];
        if (d == 0.0) {
            if (o < box.lower[a] || o > box.upper[a]) return std::nullopt;
            continue;
        }
        double ta = (box.lower[a] - o) / d, tb = (box.upper[a] - o) / d;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    if (!(t0 <= t1)) return std::nullopt;
    return std::pair{static_cast<float>(t0), static_cast<float>(t1)};
}

// The reference's traces of the same rays, through rtlab-solution in a child process. Its
// output is read like any untrusted trace; a failure leaves the oracle's answer as the expected one.
std::vector<std::optional<TraversalTrace>> referenceTraces(const SceneCaseRequest& request, const std::vector<Ray>& rays, size_t anyHitFrom,
                                                           std::vector<std::string>& notes) {
    std::vector<std::optional<TraversalTrace>> traces(rays.size());
    if (request.referenceProgram.empty()) return traces;
    TemporaryDirectory work("rtlab-view-reference");
    writeRayFile((work.path() / "rays.txt").string(), rays);
    ExternalRun run = runExternal(request.referenceProgram.string(),
                                  {"view", fs::absolute(request.scenePath).string(), "--accel", request.acceleratorName, "--rays", "rays.txt",
                                   "--any-hit-from", std::to_string(anyHitFrom), "--trace-out", "traces"},
                                  work.path(), work.path() / "log.txt", kReferenceSeconds, "build it with make build");
    if (!run.succeeded()) {
        notes.push_back("the reference (" + request.referenceProgram.filename().string() + ") could not trace these rays; expected answers are the oracle's");
        return traces;
    }
    for (size_t k = 0; k < rays.size(); ++k) {
        try {
            traces[k] = readTraversalTraceFile((work.path() / "traces" / ("trace-" + std::to_string(k) + ".bin")).string());
        } catch (const TraceFormatError& e) {
            notes.push_back(std::string("reference trace: ") + e.what());
        }
    }
    return traces;
}

// The grader's exact walk (grader/a3_grid/grid_oracle.h); none when rounding may order two crossings
// either way, as the grader then leaves the ray out of a3/dda/cell-order.
std::vector<GridCell> exactDdaCells(const UniformGrid& g, const Ray& ray, float tEnter, float tExit, std::vector<std::string>& notes) {
    std::optional<std::vector<GridCell>> walk = grader::exactCellWalk(grader::frameOf(g.bounds, g.resolution), ray, tEnter, tExit);
    if (!walk) {
        notes.push_back("DDA cells: this ray passes within rounding of a cell corner, so no walk is the expected one");
        return {};
    }
    if (walk->size() > kMaxDdaCells) walk->resize(kMaxDdaCells);
    return *walk;
}

struct ReferenceImage {
    fs::path path;
    int width = 0, height = 0;
};

// The POV-Ray reference of a scene in scenes/refs (manifest.json), by the scene file's stem.
std::optional<ReferenceImage> findReference(const fs::path& repositoryDir, const std::string& scenePath) {
    fs::path refs = repositoryDir / "scenes" / "refs";
    std::ifstream file(refs / "manifest.json");
    if (!file) return std::nullopt;
    try {
        nlohmann::json manifest = nlohmann::json::parse(file).at("references");
        std::string name = fs::path(scenePath).stem().string();
        if (!manifest.contains(name)) return std::nullopt;
        const nlohmann::json& entry = manifest[name];
        ReferenceImage ref{refs / entry.value("image", ""), entry.value("width", 0), entry.value("height", 0)};
        if (!fs::is_regular_file(ref.path)) return std::nullopt;
        return ref;
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
}

void addImages(const SceneCaseRequest& request, const Scene& scene, const Accelerator& accelerator, SceneCase& out) {
    const Camera& camera = scene.camera(request.cameraName);
    std::optional<ReferenceImage> reference = findReference(request.repositoryDir, request.scenePath);
    int width = request.width, height = request.height;
    if (width == 0 && height == 0 && reference) width = reference->width, height = reference->height;
    double aspect = camera.aspectRatio > 0.0 ? camera.aspectRatio : 4.0 / 3.0;
    if (width == 0 && height == 0) width = kDefaultWidth;
    if (width == 0) width = std::max(1, static_cast<int>(std::lround(height * aspect)));
    if (height == 0) height = std::max(1, static_cast<int>(std::lround(width / aspect)));
    auto [x, y] = *request.pixel;
    if (x < 0 || y < 0 || x >= width || y >= height)
        throw Error("--pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " + std::to_string(width) + "x" +
                    std::to_string(height) + " image");

    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.aovs = {Aov::Cost, Aov::Depth};
    settings.progress = false;
    RenderResult result = Renderer(scene, camera, accelerator).render(settings);
    out.scratch = std::make_unique<TemporaryDirectory>("rtlab-view-images");
    const fs::path& dir = out.scratch->path();
    ImageSet images;
    images.width = width;
    images.height = height;
    images.film = camera.film(width, height);
    images.render = dir / "render.png";
    writeImage(images.render.string(), result.colour, ImageWriteOptions{true, 0.0f});
    images.heatMap = dir / "heat.png";
    writeImage(images.heatMap.string(), aovImage(Aov::Cost, result.aovs, width, height, true));
    if (reference && reference->width == width && reference->height == height) {
        Image ref = readImage(reference->path.string());
        images.reference = dir / "reference.png";
        writeImage(images.reference.string(), ref, ImageWriteOptions{true, 0.0f});
        images.difference = dir / "difference.png";
        writeErrorHeatMap(result.colour, ref, images.difference.string());
        ImageComparison c = compareImages(result.colour, ref);
        char legend[256];
        std::snprintf(legend, sizeof legend, "against %s: mean error %.3g, max %.3g at (%d, %d), %.2f %% of pixels over %g codes; ",
                      reference->path.filename().string().c_str(), c.meanError, c.maxError, c.maxX, c.maxY, 100.0 * c.shareOverThreshold(),
                      c.thresholdCodes);
        images.legend = legend + errorHeatMapLegend();
    } else {
        images.legend = reference ? "the POV-Ray reference is " + std::to_string(reference->width) + "x" + std::to_string(reference->height) +
                                        ": render at that size to compare with it"
                                  : "no POV-Ray reference for this scene in scenes/refs";
    }
    // Each pixel's hit distance, and per point light whether its shadow ray is blocked.
    images.hitT.assign(size_t(width) * height, kInfinity);
    for (const PointLight& light : scene.lights) images.lights.push_back(light.position);
    images.shadowBlocked.assign(size_t(width) * height * scene.lights.size(), 0);
    CameraFilm film = images.film;
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) {
            Ray ray = film.through(px + 0.5, py + 0.5);
            TraversalStats stats;
            Hit hit = accelerator.intersect(ray, stats);
            if (!hit.found()) continue;
            size_t pixel = size_t(py) * width + px;
            images.hitT[pixel] = hit.t;
            SurfaceHit surface = scene.surfaceAt(ray, hit);
            for (size_t l = 0; l < scene.lights.size(); ++l) {
                Ray shadow = spawnShadowRay(surface.point, surface.pointError, surface.geometricNormal, scene.lights[l].position);
                images.shadowBlocked[pixel * scene.lights.size() + l] = accelerator.occluded(shadow, stats) ? 1 : 0;
            }
        }
    images.selectedPixel = std::array<int, 2>{x, y};
    images.pixelCommand = request.pixelCommand;
    out.view.images = std::move(images);
}

}  // namespace

SceneCase buildSceneCase(const SceneCaseRequest& request) {
    SceneCase out;
    auto start = std::chrono::steady_clock::now();
    auto seconds = [&start] {
        auto now = std::chrono::steady_clock::now();
        double s = std::chrono::duration<double>(now - start).count();
        start = now;
        return s;
    };
    out.scene = std::make_unique<Scene>(loadGltf(request.scenePath));
    out.loadSeconds = seconds();
    const Scene& scene = *out.scene;
    CaseView& view = out.view;
    view.scene = &scene;
    view.acceleratorName = request.acceleratorName;
    view.draw = structureDrawer(request.acceleratorName);
    view.title = fs::path(request.scenePath).filename().string() + " through " + request.acceleratorName;

    AcceleratorSpec spec;
    spec.name = request.acceleratorName;
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
    PrimitiveSet primitives(scene);
    seconds();
    accelerator->build(primitives);
    out.buildSeconds = seconds();
    view.structure = accelerator->structure();

    // The rays: given, or a pixel's camera ray and a shadow ray to each point light from its hit.
    std::vector<Ray> rays = request.rays;
    std::vector<std::string> labels;
    size_t anyHitFrom = rays.size();
    for (size_t k = 0; k < rays.size(); ++k) labels.push_back(request.rays.size() == 1 && !request.rayLabel.empty() ? request.rayLabel : "ray " + std::to_string(k));
    if (request.pixel) {
        addImages(request, scene, *accelerator, out);
        const ImageSet& images = *view.images;
        auto [x, y] = *request.pixel;
        Ray camera = images.film.through(x + 0.5, y + 0.5);
        rays = {camera};
        labels = {"camera ray of pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"};
        anyHitFrom = 1;
        TraversalStats stats;
        Hit hit = accelerator->intersect(camera, stats);
        if (hit.found()) {
            SurfaceHit surface = scene.surfaceAt(camera, hit);
            for (size_t l = 0; l < scene.lights.size(); ++l) {
                rays.push_back(spawnShadowRay(surface.point, surface.pointError, surface.geometricNormal, scene.lights[l].position));
                labels.push_back("shadow ray to light " + std::to_string(l) + " (" + scene.lights[l].name + ")");
            }
        }
        view.title += ", pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
    }

    Oracle oracle(scene);
    std::vector<std::optional<TraversalTrace>> reference = referenceTraces(request, rays, anyHitFrom, view.notes);
    for (size_t k = 0; k < rays.size(); ++k) {
        bool anyHit = k >= anyHitFrom;
        TracedQuery q = traceQuery(*accelerator, rays[k], anyHit);
        RayCase c;
        c.ray = rays[k];
        c.label = labels[k] + (anyHit ? " (any hit)" : "") + ": " + describeRay(rays[k]);
        c.student = q.answer;
        c.studentTrace = std::move(q.trace);
        c.expected = oracleAnswer(oracle, rays[k], anyHit);
        if (reference[k]) {
            c.expectedTrace = std::move(reference[k]);
            c.expectedSource = "the exact oracle; steps from " + request.referenceProgram.filename().string();
        }
        if (!q.problem.empty()) view.notes.push_back(labels[k] + ": the traversal stopped: " + q.problem);
        view.rays.push_back(std::move(c));
    }

    // a3: the DDA's cells for the first ray, the linked code's against the exact walk.
    const auto* grid = dynamic_cast<const GridAccelerator*>(accelerator.get());
    if (grid) view.gridResolution = grid->grid().resolution;
    if (grid && request.ddaWalk && !rays.empty()) {
        const UniformGrid& g = grid->grid();
        if (auto segment = segmentIn(g.bounds, rays[0])) {
            DdaCells dda;
            dda.bounds = g.bounds;
            dda.resolution = g.resolution;
            dda.ray = 0;
            try {
                dda.student = request.ddaWalk(g, rays[0], segment->first, segment->second, kMaxDdaCells);
            } catch (const NotImplemented& e) {
                view.notes.push_back(std::string("DDA cells: ") + e.what());
            }
            dda.expected = exactDdaCells(g, rays[0], segment->first, segment->second, view.notes);
            view.dda = std::move(dda);
        }
    }
    return out;
}

void writeRayTraces(const std::string& scenePath, const std::string& acceleratorName, const std::vector<Ray>& rays, size_t anyHitFrom,
                    const fs::path& outDir) {
    Scene scene = loadGltf(scenePath);
    AcceleratorSpec spec;
    spec.name = acceleratorName;
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
    PrimitiveSet primitives(scene);
    accelerator->build(primitives);
    fs::create_directories(outDir);
    for (size_t k = 0; k < rays.size(); ++k) {
        TracedQuery q = traceQuery(*accelerator, rays[k], k >= anyHitFrom);
        writeTraversalTraceFile((outDir / ("trace-" + std::to_string(k) + ".bin")).string(), q.trace);
    }
}

}  // namespace rtlab::viewer
