// rtlab refs [SCENE...] [--scenes DIR] [--force] [--check] [--hits] [--parity] [--blender]:
// reference renders (docs/verification.md). Without --check/--hits/--parity, renders
// DIR/refs/<name>.png with POV-Ray for every DIR/*.gltf (with --blender: DIR/refs/<name>.exr
// with Blender Cycles for every DIR/radiometry/*.gltf), every scene the manifest already lists
// and every SCENE given, skipping those whose inputs (scene hash, exporter, renderer version,
// settings) are unchanged. --check re-renders into a temporary folder and compares with the
// committed images; --hits traces a ray set per scene with POV-Ray's trace() and compares it
// with the oracle; --parity renders every reference's scene with our renderer (the
// implementation this executable links) and checks it against the reference. Exit status 1 on
// any mismatch. The renderers themselves: cli/reference_renderer.h.
#include "cli/commands.h"
#include "cli/reference_renderer.h"
#include "framework/core/error.h"
#include "framework/core/sha256.h"
#include "framework/external/reference_manifest.h"
#include "framework/external/reference_policy.h"
#include "framework/external/temporary_directory.h"
#include "framework/pov/pov_trace.h"
#include "framework/verification/image_compare.h"
#include "framework/scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace rtlab::cli {

std::ostream& refsLine(const std::string& name) { return std::cout << "  " << std::left << std::setw(16) << name << " "; }

std::string fixedDigits(double value, int digits) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

namespace {
namespace fs = std::filesystem;

struct SceneJob {
    std::string name;
    fs::path scene;
};

// Where everything lives: DIR, DIR/refs, the manifest, and the root scene paths are relative to.
struct RefsLayout : ReferenceFolder {
    fs::path scenesDir;

    RefsLayout(const std::string& dir, const std::string& manifestFile) : scenesDir(dir) {
        if (!fs::is_directory(scenesDir))
            throw Error(dir + ": no such scenes folder (run from the repository root or pass --scenes)");
        refsDir = scenesDir / "refs";
        manifestPath = refsDir / manifestFile;
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

// The renderer's scenes in DIR, those the manifest lists (e.g. the bunny, fetched at set-up)
// and those named on the command line; a manifest scene that is missing is reported and
// skipped, and so is a scene the renderer cannot render as ours does (with the reason).
std::vector<SceneJob> collectScenes(const RefsOptions& options, const RefsLayout& layout,
                                    const ReferenceManifest& manifest, const ReferenceRenderer& renderer) {
    std::vector<fs::path> paths;
    if (!options.scenePaths.empty()) {
        for (const std::string& path : options.scenePaths) {
            if (!fs::is_regular_file(path)) throw Error(path + ": no such scene file");
            paths.push_back(path);
        }
    } else {
        fs::path folder = layout.scenesDir / renderer.scenesSubfolder;
        if (fs::is_directory(folder))
            for (const auto& file : fs::directory_iterator(folder))
                if (file.path().extension() == ".gltf") paths.push_back(file.path());
        for (const auto& [name, entry] : manifest.entries) {
            fs::path scene = layout.root / entry.scene;
            if (fs::is_regular_file(scene))
                paths.push_back(scene);
            else
                refsLine(name) << "skipped: " << entry.scene << " not found (run scripts/fetch-models)\n";
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
    std::erase_if(jobs, [&renderer](const SceneJob& job) {
        std::string reason = renderer.skipReason(loadGltf(job.scene.string()));
        if (!reason.empty()) refsLine(job.name) << "skipped: " << reason << "\n";
        return !reason.empty();
    });
    return jobs;
}

ReferenceEntry recipeFor(const SceneJob& job, const Scene& scene, const RefsLayout& layout,
                         const ReferenceRenderer& renderer) {
    ReferenceEntry entry;
    entry.name = job.name;
    entry.scene = fs::absolute(job.scene).lexically_normal().lexically_relative(layout.root).generic_string();
    entry.inputs = hashSceneInputs(job.scene, layout.root);
    entry.camera = scene.camera("").name;
    entry.exporter = renderer.exporter;
    entry.renderer = renderer.version;
    entry.width = renderer.width;
    entry.height = renderer.height;
    entry.settings = renderer.settings;
    entry.image = job.name + renderer.imageExtension;
    return entry;
}

void renderReferences(const RefsOptions& options, const RefsLayout& layout, ReferenceManifest& manifest,
                      const std::vector<SceneJob>& jobs, const ReferenceRenderer& renderer) {
    fs::create_directories(layout.refsDir);
    for (const SceneJob& job : jobs) {
        Scene scene = loadGltf(job.scene.string());
        ReferenceEntry wanted = recipeFor(job, scene, layout, renderer);
        std::string reason = whyRender(wanted, manifest, layout, renderer.name, options.force);
        if (reason.empty()) {
            refsLine(job.name) << "up to date\n";
            continue;
        }
        Stopwatch clock;
        fs::path image = layout.refsDir / wanted.image;
        renderer.render(scene, scene.camera(wanted.camera), image);
        wanted.imageSha256 = sha256OfFile(image.string());
        manifest.entries[job.name] = wanted;
        manifest.save(layout.manifestPath);  // after every scene: an interrupted run keeps its work
        refsLine(job.name) << "rendered " << wanted.width << "x" << wanted.height << " in "
                           << fixedDigits(clock.seconds(), 1) << " s (" << reason << ") -> " << image.string() << "\n";
    }
}

// Runs check(job, entry, scene) on every scene whose reference is current; check returns
// whether the scene passed. A scene without a current reference fails (staleReference says why).
// Returns the names of the scenes that failed.
template <typename Check>
std::vector<std::string> checkCurrentReferences(const RefsLayout& layout, const ReferenceManifest& manifest,
                                                const std::vector<SceneJob>& jobs, const std::string& refsCommand,
                                                Check check) {
    std::vector<std::string> failed;
    for (const SceneJob& job : jobs) {
        std::string stale = staleReference(job.name, job.scene, manifest, layout);
        if (!stale.empty()) refsLine(job.name) << "FAIL: " << stale << " (run " << refsCommand << ")\n";
        if (!stale.empty() || !check(job, manifest.entries.at(job.name), loadGltf(job.scene.string()))) failed.push_back(job.name);
    }
    return failed;
}

// Re-renders with the entry's own size: the references are compared pixel for pixel (a PNG's
// date or an EXR's render time differ, the pixels must not, beyond the renderer's
// recheckTolerance). Returns the names that differ.
std::vector<std::string> checkReferences(const RefsLayout& layout, const ReferenceManifest& manifest,
                                         const std::vector<SceneJob>& jobs, const std::string& refsCommand,
                                         const ReferenceRenderer& renderer) {
    TemporaryDirectory work("rtlab-refs-check");
    return checkCurrentReferences(layout, manifest, jobs, refsCommand,
                                  [&](const SceneJob& job, const ReferenceEntry& entry, const Scene& scene) {
        fs::path committed = layout.refsDir / entry.image;
        fs::path fresh = work.path() / entry.image;
        if (entry.width != renderer.width || entry.height != renderer.height || entry.settings != renderer.settings) {
            refsLine(job.name) << "FAIL: made with other settings (" << entry.width << "x" << entry.height << " "
                               << entry.settings << "; run " << refsCommand << ")\n";
            return false;
        }
        renderer.render(scene, scene.camera(entry.camera), fresh);
        ImageComparison c = compareImages(fresh.string(), committed.string(), 0.0);
        ImageAgreement verdict = agreementWith(c, committed.string(), renderer.recheckTolerance);
        refsLine(job.name) << (verdict.identical ? "identical" : verdict.agrees ? "agrees, not bit for bit" : "FAIL: differs") << " ("
                           << c.pixelCount << " pixels, " << c.pixelsOverThreshold << " differ, max ";
        if (c.wholeCodes)
            std::cout << c.maxCodes() << " codes";
        else
            std::cout << c.maxError;
        if (!verdict.identical && renderer.recheckTolerance > 0.0)
            std::cout << ", RMS " << std::setprecision(2) << verdict.relativeRms << " of the mean, allowed " << renderer.recheckTolerance
                      << std::setprecision(6);
        std::cout << ")";
        if (entry.renderer != renderer.version) std::cout << " [reference made with " << entry.renderer << "]";
        std::cout << "\n";
        return verdict.agrees;
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
                << "), normal 1-|cos| max " << c.maxNormalError << ", POV-Ray " << fixedDigits(povSeconds, 1) << " s";
        refsLine(job.name) << (c.agrees() ? "agree: " : "FAIL: ") << figures.str() << "\n";
        for (const std::string& mismatch : c.mismatches) std::cout << "      " << mismatch << "\n";
        if (!c.agrees()) failed.push_back(job.name);
    }
    return failed;
}

void refs(const RefsOptions& options) {
    ReferenceRenderer renderer = options.blender ? blenderReferenceRenderer(options) : povReferenceRenderer(options);
    std::string refsCommand = options.blender ? "rtlab refs --blender" : "rtlab refs";
    RefsLayout layout(options.scenesDir, renderer.manifestFile);
    ReferenceManifest manifest = ReferenceManifest::load(layout.manifestPath);
    manifest.about = renderer.about;
    std::cout << "refs: " << renderer.version << ", exporter " << renderer.exporter << ", " << renderer.width << "x"
              << renderer.height << " " << renderer.settings << ", " << layout.refsDir.string() << "\n";
    std::vector<SceneJob> jobs = collectScenes(options, layout, manifest, renderer);

    if (!options.check && !options.hits && !options.parity) {
        renderReferences(options, layout, manifest, jobs, renderer);
        return;
    }
    std::vector<std::string> failed;
    if (options.check) {
        std::cout << "re-rendering and comparing with the committed references:\n";
        for (const std::string& name : checkReferences(layout, manifest, jobs, refsCommand, renderer))
            failed.push_back(name);
    }
    if (options.hits) {
        std::cout << "POV-Ray trace() against the oracle (seed " << options.seed << "):\n";
        for (const std::string& name : checkHitSets(options, jobs)) failed.push_back("hits:" + name);
    }
    if (options.parity) {
        std::cout << (options.blender ? "our renderer against the references (statistically):\n"
                                      : "our renderer against the references (median 0 codes, >= 99.9 % within 2 codes):\n");
        for (const std::string& name : checkCurrentReferences(
                 layout, manifest, jobs, refsCommand, [&](const SceneJob& job, const ReferenceEntry& entry, const Scene& scene) {
                     return renderer.parity(job.name, scene, scene.camera(entry.camera), layout.refsDir / entry.image);
                 }))
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
        "refs", "Render POV-Ray (or, with --blender, Blender Cycles) references for the scenes (only what changed); "
                "check them, trace() hit sets, or our renders against them (docs/verification.md)");
    command->add_option("scene", options->scenePaths,
                        "Scene files (default: DIR/*.gltf, with --blender DIR/radiometry/*.gltf, and every scene the "
                        "manifest lists)");
    command->add_option("--scenes", options->scenesDir, "Scenes folder; references go to DIR/refs")
        ->capture_default_str();
    command->add_option("--width", options->width, "Reference width (default 320, with --blender 160)")
        ->check(CLI::Range(1, 8192));
    command->add_option("--height", options->height, "Reference height (default 240, with --blender 120)")
        ->check(CLI::Range(1, 8192));
    command->add_flag("--force", options->force, "Re-render even references that are up to date");
    command->add_flag("--check", options->check,
                      "Re-render into a temporary folder and compare with the committed references (exit 1 on mismatch)");
    auto* hits = command->add_flag(
        "--hits", options->hits,
        "Trace a ray set per scene with POV-Ray's trace() and compare with the oracle (exit 1 on mismatch)");
    command->add_flag("--parity", options->parity,
                      "Render every reference's scene with this executable's renderer and check it against the "
                      "reference: POV-Ray median 0 codes, >= 99.9 % of pixels within 2 codes; Blender the "
                      "statistical test of docs/verification.md (exit 1 when missed)");
    command->add_option("--parity-dir", options->parityDir,
                        "With --parity: keep our renders (NAME.rtlab.png and heat maps NAME.heat.png; with --blender "
                        "the mean of the replicates, NAME.rtlab.exr) here");
    command->add_option("--rays", options->rays, "Rays per scene for --hits")->capture_default_str()->check(CLI::Range(1, 10000000));
    command->add_option("--seed", options->seed, "Seed of the --hits ray sets")->capture_default_str();
    auto* blender = command->add_flag(
        "--blender", options->blender,
        "Blender Cycles references (EXR) of the radiometry scenes instead of POV-Ray's: scenes/refs/NAME.exr, "
        "scenes/refs/blender-manifest.json");
    command->add_option("--samples", options->samples, "With --blender: Cycles samples per pixel (default 512)")
        ->check(CLI::Range(1, 1 << 24))
        ->needs(blender);
    command->add_option("--replicates", options->replicates,
                        "With --blender --parity: our renders (one sample per pixel each) to compare")
        ->capture_default_str()
        ->check(CLI::Range(2, 1 << 20))
        ->needs(blender);
    hits->excludes(blender);
    command->callback([options] { refs(*options); });
}

}  // namespace rtlab::cli
