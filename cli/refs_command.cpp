// rtlab refs [SCENE...] [--scenes DIR] [--force] [--check] [--hits] [--parity]: POV-Ray
// references (docs/verification.md). Without --check/--hits/--parity, renders DIR/refs/<name>.png for every
// DIR/*.gltf, every scene the manifest already lists and every SCENE given, skipping those whose
// inputs (scene hash, exporter, POV-Ray version, settings) are unchanged. --check re-renders
// into a temporary folder and compares with the committed images; --hits traces a ray set per
// scene with POV-Ray's trace() and compares it with the oracle; --parity renders every
// reference's scene with our renderer (the implementation this executable links) and checks the
// parity target. Exit status 1 on any mismatch.
#include "framework/accel/accelerator.h"
#include "cli/commands.h"
#include "framework/core/error.h"
#include "framework/core/sha256.h"
#include "framework/pov/pov_exporter.h"
#include "framework/pov/pov_reference.h"
#include "framework/pov/pov_trace.h"
#include "framework/pov/povray_process.h"
#include "framework/pov/reference_manifest.h"
#include "framework/render/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/render/renderer.h"
#include "framework/scene/gltf_loader.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace rtlab::cli {
namespace {
namespace fs = std::filesystem;

struct RefsOptions {
    std::vector<std::string> scenePaths;
    std::string scenesDir = "scenes";
    int width = 320;
    int height = 240;
    bool force = false;
    bool check = false;
    bool hits = false;
    bool parity = false;
    std::string parityDir;
    size_t rays = 3000;
    uint64_t seed = 1;
};

struct SceneJob {
    std::string name;
    fs::path scene;
};

// Where everything lives: DIR, DIR/refs, the manifest, and the root scene paths are relative to.
struct RefsLayout {
    fs::path scenesDir;
    fs::path refsDir;
    fs::path manifestPath;
    fs::path root;

    explicit RefsLayout(const std::string& dir)
        : scenesDir(dir), refsDir(scenesDir / "refs"), manifestPath(refsDir / "manifest.json") {
        if (!fs::is_directory(scenesDir))
            throw Error(dir + ": no such scenes folder (run from the repository root or pass --scenes)");
        fs::path absolute = fs::absolute(scenesDir).lexically_normal();
        if (absolute.filename().empty()) absolute = absolute.parent_path();  // "scenes/"
        root = absolute.parent_path();
    }
};

class Stopwatch {
public:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string fixed(double value, int digits) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

std::ostream& line(const std::string& name) { return std::cout << "  " << std::left << std::setw(16) << name << " "; }

// The scenes of DIR, those the manifest lists (e.g. the bunny, fetched at set-up) and those
// named on the command line; a manifest scene that is missing is reported and skipped.
std::vector<SceneJob> collectScenes(const RefsOptions& options, const RefsLayout& layout,
                                    const ReferenceManifest& manifest) {
    std::vector<fs::path> paths;
    if (!options.scenePaths.empty()) {
        for (const std::string& path : options.scenePaths) {
            if (!fs::is_regular_file(path)) throw Error(path + ": no such scene file");
            paths.push_back(path);
        }
    } else {
        for (const auto& file : fs::directory_iterator(layout.scenesDir))
            if (file.path().extension() == ".gltf") paths.push_back(file.path());
        for (const auto& [name, entry] : manifest.entries) {
            fs::path scene = layout.root / entry.scene;
            if (fs::is_regular_file(scene))
                paths.push_back(scene);
            else
                line(name) << "skipped: " << entry.scene << " not found (run scripts/fetch-models)\n";
        }
    }
    std::vector<SceneJob> jobs;
    std::set<fs::path> seen;
    for (const fs::path& path : paths) {
        fs::path canonical = fs::weakly_canonical(path);
        if (!seen.insert(canonical).second) continue;
        std::string name = path.stem().string();
        for (const SceneJob& job : jobs)
            if (job.name == name)
                throw Error(path.string() + ": a second scene named '" + name + "' (also " + job.scene.string() + ")");
        jobs.push_back({name, path});
    }
    std::sort(jobs.begin(), jobs.end(), [](const SceneJob& a, const SceneJob& b) { return a.name < b.name; });
    return jobs;
}

ReferenceEntry recipeFor(const SceneJob& job, const Scene& scene, const RefsOptions& options,
                         const RefsLayout& layout, const std::string& povray) {
    ReferenceEntry entry;
    entry.name = job.name;
    entry.scene = fs::absolute(job.scene).lexically_normal().lexically_relative(layout.root).generic_string();
    entry.inputs = hashSceneInputs(job.scene, layout.root);
    entry.camera = scene.camera("").name;
    entry.exporter = std::string(kPovExporterVersion);
    entry.povray = povray;
    entry.width = options.width;
    entry.height = options.height;
    entry.settings = povReferenceSettings(options.width, options.height);
    entry.image = job.name + ".png";
    return entry;
}

std::string whyRender(const ReferenceEntry& wanted, const ReferenceManifest& manifest, const RefsLayout& layout,
                      bool force) {
    if (force) return "forced";
    auto found = manifest.entries.find(wanted.name);
    if (found == manifest.entries.end()) return "new";
    const ReferenceEntry& old = found->second;
    if (old.inputs != wanted.inputs || old.scene != wanted.scene) return "scene changed";
    if (old.exporter != wanted.exporter) return "exporter changed";
    if (old.povray != wanted.povray) return "POV-Ray version changed";
    if (!old.sameRecipe(wanted)) return "settings changed";
    fs::path image = layout.refsDir / old.image;
    if (!fs::exists(image)) return "image missing";
    if (sha256OfFile(image.string()) != old.imageSha256) return "image modified";
    return "";
}

void renderReferences(const RefsOptions& options, const RefsLayout& layout, ReferenceManifest& manifest,
                      const std::vector<SceneJob>& jobs, const std::string& povray) {
    fs::create_directories(layout.refsDir);
    for (const SceneJob& job : jobs) {
        Scene scene = loadGltf(job.scene.string());
        ReferenceEntry wanted = recipeFor(job, scene, options, layout, povray);
        std::string reason = whyRender(wanted, manifest, layout, options.force);
        if (reason.empty()) {
            line(job.name) << "up to date\n";
            continue;
        }
        Stopwatch clock;
        fs::path image = layout.refsDir / wanted.image;
        renderPovReference(scene, scene.camera(wanted.camera), wanted.width, wanted.height, image);
        wanted.imageSha256 = sha256OfFile(image.string());
        manifest.entries[job.name] = wanted;
        manifest.save(layout.manifestPath);  // after every scene: an interrupted run keeps its work
        line(job.name) << "rendered " << wanted.width << "x" << wanted.height << " in " << fixed(clock.seconds(), 1)
                       << " s (" << reason << ") -> " << image.string() << "\n";
    }
}

// The manifest entry of a scene whose reference is current; otherwise prints why not and
// returns nullptr.
const ReferenceEntry* currentEntry(const SceneJob& job, const RefsLayout& layout, const ReferenceManifest& manifest) {
    auto found = manifest.entries.find(job.name);
    if (found == manifest.entries.end()) {
        line(job.name) << "FAIL: no reference in " << layout.manifestPath.string() << " (run rtlab refs)\n";
        return nullptr;
    }
    const ReferenceEntry& entry = found->second;
    if (hashSceneInputs(job.scene, layout.root) != entry.inputs) {
        line(job.name) << "FAIL: " << entry.scene << " changed since its reference was rendered (run rtlab refs)\n";
        return nullptr;
    }
    if (!fs::exists(layout.refsDir / entry.image)) {
        line(job.name) << "FAIL: " << (layout.refsDir / entry.image).string() << " is missing (run rtlab refs)\n";
        return nullptr;
    }
    return &entry;
}

// Runs check(job, entry, scene) on every scene whose reference is current; check returns
// whether the scene passed. A scene without a current reference fails (currentEntry says why).
// Returns the names of the scenes that failed.
template <typename Check>
std::vector<std::string> checkCurrentReferences(const RefsLayout& layout, const ReferenceManifest& manifest,
                                                const std::vector<SceneJob>& jobs, Check check) {
    std::vector<std::string> failed;
    for (const SceneJob& job : jobs) {
        const ReferenceEntry* entry = currentEntry(job, layout, manifest);
        if (!entry || !check(job, *entry, loadGltf(job.scene.string()))) failed.push_back(job.name);
    }
    return failed;
}

// Returns the names of the references that do not match.
std::vector<std::string> checkReferences(const RefsLayout& layout, const ReferenceManifest& manifest,
                                         const std::vector<SceneJob>& jobs, const std::string& povray) {
    TemporaryDirectory work("rtlab-refs-check");
    return checkCurrentReferences(layout, manifest, jobs,
                                  [&](const SceneJob& job, const ReferenceEntry& entry, const Scene& scene) {
        fs::path committed = layout.refsDir / entry.image;
        fs::path fresh = work.path() / entry.image;
        renderPovReference(scene, scene.camera(entry.camera), entry.width, entry.height, fresh);
        ImageComparison c = compareImages(fresh.string(), committed.string(), 0.0);
        bool identical = c.pixelsOverThreshold == 0;
        line(job.name) << (identical ? "identical" : "FAIL: differs") << " (" << c.pixelCount << " pixels, "
                       << c.pixelsOverThreshold << " differ, max " << c.maxCodes() << " codes)";
        if (entry.povray != povray) std::cout << " [reference made with " << entry.povray << "]";
        std::cout << "\n";
        return identical;
    });
}

std::vector<std::string> checkHitSets(const RefsOptions& options, const std::vector<SceneJob>& jobs) {
    std::vector<std::string> failed;
    for (const SceneJob& job : jobs) {
        Scene scene = loadGltf(job.scene.string());
        std::vector<OracleRay> rays = makeHitSetRays(scene, scene.camera(""), options.rays, options.seed);
        Stopwatch clock;
        std::vector<PovTraceHit> hits = traceWithPovray(scene, rays);
        double povSeconds = clock.seconds();
        HitSetComparison c = compareWithOracle(scene, rays, hits);
        std::ostringstream figures;
        figures << std::setprecision(2) << c.rays << " rays (" << c.nearEdge << " near an edge), hit/miss agree "
                << c.hitMissAgreements << "/" << c.compared << ", " << c.bothHit << " hits, point error max "
                << c.maxPointError << " median " << c.medianPointError << " (tolerance " << c.pointTolerance
                << "), normal 1-|cos| max " << c.maxNormalError << ", POV-Ray " << fixed(povSeconds, 1) << " s";
        line(job.name) << (c.agrees() ? "agree: " : "FAIL: ") << figures.str() << "\n";
        for (const std::string& mismatch : c.mismatches) std::cout << "      " << mismatch << "\n";
        if (!c.agrees()) failed.push_back(job.name);
    }
    return failed;
}

// The parity target of docs/verification.md: median pixel error 0 codes and at least 99.9 %
// of pixels within 2 codes of POV-Ray.
constexpr double kParityCodes = 2.0;
constexpr double kParityShare = 0.999;

std::vector<std::string> checkParity(const RefsOptions& options, const RefsLayout& layout,
                                     const ReferenceManifest& manifest, const std::vector<SceneJob>& jobs) {
    TemporaryDirectory work("rtlab-refs-parity");
    fs::path outputDir = options.parityDir.empty() ? work.path() : fs::path(options.parityDir);
    fs::create_directories(outputDir);
    return checkCurrentReferences(layout, manifest, jobs,
                                  [&](const SceneJob& job, const ReferenceEntry& entry, const Scene& scene) {
        PrimitiveSet primitives(scene);
        auto accelerator = makeAccelerator(AcceleratorSpec{});
        accelerator->build(primitives);
        RenderSettings settings;
        settings.width = entry.width;
        settings.height = entry.height;
        settings.progress = false;
        RenderResult result = Renderer(scene, scene.camera(entry.camera), *accelerator).render(settings);
        fs::path render = outputDir / (job.name + ".rtlab.png");
        writeImage(render.string(), result.colour);
        fs::path reference = layout.refsDir / entry.image;
        ImageComparison c = compareImages(render.string(), reference.string(), kParityCodes);
        double within = 1.0 - c.shareOverThreshold();
        bool meets = c.medianPixelCodes == 0.0 && within >= kParityShare;
        line(job.name) << (meets ? "meets target: " : "FAIL: ") << "median " << c.medianPixelCodes
                       << " codes, exact " << fixed(100.0 * c.pixelsByCodes[0] / c.pixelCount, 3) << " %, within 2 codes "
                       << fixed(100.0 * within, 3) << " % (" << c.pixelsOverThreshold << " of " << c.pixelCount
                       << " beyond), max " << c.maxCodes() << " codes";
        if (!options.parityDir.empty()) {
            fs::path heat = outputDir / (job.name + ".heat.png");
            writeErrorHeatMap(render.string(), reference.string(), heat.string());
            std::cout << ", heat map " << heat.string();
        }
        std::cout << "\n";
        return meets;
    });
}

void refs(const RefsOptions& options) {
    RefsLayout layout(options.scenesDir);
    ReferenceManifest manifest = ReferenceManifest::load(layout.manifestPath);
    std::string povray = povrayVersion();
    std::cout << "refs: " << povray << ", exporter " << kPovExporterVersion << ", " << layout.refsDir.string()
              << "\n";
    std::vector<SceneJob> jobs = collectScenes(options, layout, manifest);

    if (!options.check && !options.hits && !options.parity) {
        renderReferences(options, layout, manifest, jobs, povray);
        return;
    }
    std::vector<std::string> failed;
    if (options.check) {
        std::cout << "re-rendering and comparing with the committed references:\n";
        for (const std::string& name : checkReferences(layout, manifest, jobs, povray)) failed.push_back(name);
    }
    if (options.hits) {
        std::cout << "POV-Ray trace() against the oracle (seed " << options.seed << "):\n";
        for (const std::string& name : checkHitSets(options, jobs)) failed.push_back("hits:" + name);
    }
    if (options.parity) {
        std::cout << "our renderer against the references (median 0 codes, >= 99.9 % within 2 codes):\n";
        for (const std::string& name : checkParity(options, layout, manifest, jobs))
            failed.push_back("parity:" + name);
    }
    if (!failed.empty()) {
        std::string names;
        for (const std::string& name : failed) names += (names.empty() ? "" : ", ") + name;
        throw Error("refs: " + std::to_string(failed.size()) + " check(s) failed: " + names);
    }
}

}  // namespace

void addRefsCommand(CLI::App& app) {
    auto options = std::make_shared<RefsOptions>();
    CLI::App* command = app.add_subcommand(
        "refs", "Render POV-Ray references for the scenes (only what changed); check them, trace() hit sets, "
               "or our renders against them (docs/verification.md)");
    command->add_option("scene", options->scenePaths,
                        "Scene files (default: DIR/*.gltf and every scene the manifest lists)");
    command->add_option("--scenes", options->scenesDir, "Scenes folder; references go to DIR/refs")
        ->capture_default_str();
    command->add_option("--width", options->width, "Reference width")->capture_default_str()->check(CLI::Range(1, 8192));
    command->add_option("--height", options->height, "Reference height")->capture_default_str()->check(CLI::Range(1, 8192));
    command->add_flag("--force", options->force, "Re-render even references that are up to date");
    command->add_flag("--check", options->check,
                      "Re-render into a temporary folder and compare with the committed references (exit 1 on mismatch)");
    command->add_flag("--hits", options->hits,
                      "Trace a ray set per scene with POV-Ray's trace() and compare with the oracle (exit 1 on mismatch)");
    command->add_flag("--parity", options->parity,
                      "Render every reference's scene with this executable's renderer and check the parity "
                      "target: median 0 codes, >= 99.9 % of pixels within 2 codes (exit 1 when missed)");
    command->add_option("--parity-dir", options->parityDir,
                        "With --parity: keep our renders and write heat maps (NAME.rtlab.png, NAME.heat.png) here");
    command->add_option("--rays", options->rays, "Rays per scene for --hits")->capture_default_str()->check(CLI::Range(1, 10000000));
    command->add_option("--seed", options->seed, "Seed of the --hits ray sets")->capture_default_str();
    command->callback([options] { refs(*options); });
}

}  // namespace rtlab::cli
