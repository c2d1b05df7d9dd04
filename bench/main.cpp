// rtlab-bench / rtlab-solution-bench (docs/performance.md): rtlab's accelerators side by side
// with Embree on the scenes, rays and timing protocol of docs/performance.md#what-is-measured,
// and run time against error. `rtlab bench` and `rtlab-solution bench` run these executables; they
// are separate so that only they link Embree.
#include "bench/bench_scenes.h"
#include "bench/convergence.h"
#include "bench/embree_race.h"
#include "bench/parameter_sweep.h"
#include "bench/reference_check.h"
#include "bench/grid_report.h"
#include "bench/render_race.h"
#include "bench/report.h"
#include "bench/structures_report.h"
#include "bench/target_tables.h"
#include "bench/throughput.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/core/error.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

using namespace rtlab;
using namespace rtlab::bench;

namespace {

struct Options {
    std::vector<std::string> scenes;
    std::vector<std::string> systems;
    std::vector<std::string> accelerators;  // --accel NAME: the row rtlab:NAME
    int maxLeaf = 4;
    std::string outDir;
    std::string modelsDir = RTLAB_DEFAULT_MODELS_DIR;
    bool quick = false;
    bool checkReferenceHits = false;
    std::string checkAccelerator = "bvh-buckets:12";
    bool skipThroughput = false;
    bool skipRace = false;
    RaceOptions race;
    bool skipConvergence = false;
    bool skipParameters = false;
    bool skipEstimators = false;
    bool skipRender = false;
    RenderRaceOptions renderRace;
    std::string convergenceScene = "bunny";
    std::string estimatorScene = "scenes/radiometry/penumbra.gltf";
    std::string parameterScene = "engine";
};

int runBench(const Options& options) {
    namespace fs = std::filesystem;
    // A bad --accel fails before a scene is loaded, in one line naming it.
    for (const std::string& name : options.accelerators) chooseAccelerator(AcceleratorSpec{name});
    if (options.checkReferenceHits) {
        std::vector<std::string> scenes =
            options.scenes.empty() ? std::vector<std::string>{"bunny", "engine", "sphereflake", "randsoup"} : options.scenes;
        return checkReference(scenes, options.modelsDir, options.checkAccelerator) ? 0 : 1;
    }
    if (!options.outDir.empty()) fs::create_directories(options.outDir);
    auto outPath = [&](const std::string& file) { return (fs::path(options.outDir) / file).string(); };

    std::cout << "# rtlab bench" << (options.quick ? " --quick" : "") << "\n";
    if (!options.skipThroughput) {
        ThroughputOptions throughput;
        throughput.scenes = options.scenes.empty() ? (options.quick ? std::vector<std::string>{"bunny"} : defaultSceneNames())
                                                   : options.scenes;
        throughput.systems = options.systems;
        for (const std::string& name : options.accelerators) throughput.systems.push_back("rtlab:" + name);
        // --accel alone still gets its peer row.
        if (!options.accelerators.empty() && options.systems.empty()) throughput.systems.push_back("embree:medium");
        throughput.maxLeaf = options.maxLeaf;
        throughput.modelsDir = options.modelsDir;
        if (options.quick) {
            throughput.rayStride = 16;
            throughput.protocol = TraceProtocol{0.0, 1, 1, 0.0};
            throughput.buildRepeats = 1;
        }
        std::vector<ThroughputRecord> records = runThroughput(throughput);
        std::cout << "\n## Throughput" << (options.quick ? " (--quick: every 16th ray, one pass)" : "") << "\n";
        writeMarkdown(std::cout, records);
        writeTargets(std::cout, records);
        writeStructureTargets(std::cout, records);
        if (!options.outDir.empty()) {
            writeCsv(outPath("results.csv"), records);
            writeGridSweepSvg(outPath("grid-sweep.svg"), records);
            writeStructuresSvg(outPath("structures.svg"), records);
        }
    }
    if (!options.skipRace) {
        RaceOptions race = options.race;
        race.modelsDir = options.modelsDir;
        if (!options.scenes.empty()) race.scenes = options.scenes;
        if (options.quick) race = quickRace(race);
        RaceResult result = runRace(race);
        std::cout << "\n## The fast path against Embree, alternating" << (options.quick ? " (--quick)" : "") << "\n\n";
        writeRaceMarkdown(std::cout, result);
        if (!options.outDir.empty()) writeRaceCsv(outPath("race.csv"), result);
    }
    if (!options.skipConvergence) {
        ConvergenceOptions convergence;
        convergence.scene = options.convergenceScene;
        convergence.modelsDir = options.modelsDir;
        if (options.quick) convergence = quickConvergence(convergence);
        ConvergenceResult result = runConvergence(convergence);
        std::cout << "\n## Image error against samples per pixel\n";
        writeConvergenceMarkdown(std::cout, result);
        if (!options.outDir.empty()) {
            writeConvergenceCsv(outPath("convergence.csv"), result);
            writeConvergenceSvg(outPath("convergence.svg"), result);
        }
    }
    if (!options.skipEstimators) {
        ConvergenceResult result = runConvergence(estimatorComparison(options.estimatorScene, options.quick));
        std::cout << "\n## Estimators of direct light: error against samples and time\n";
        writeConvergenceMarkdown(std::cout, result);
        if (!options.outDir.empty()) {
            writeConvergenceCsv(outPath("estimators.csv"), result);
            writeConvergenceSvg(outPath("estimators.svg"), result);
        }
    }
    if (!options.skipParameters) {
        ParameterSweepOptions sweep;
        sweep.scene = options.quick ? "bunny" : options.parameterScene;
        sweep.modelsDir = options.modelsDir;
        if (options.quick) sweep = quickParameterSweep(sweep);
        std::vector<ParameterPoint> points = runParameterSweep(sweep);
        std::cout << "\n## Accelerator parameters: build time, trace time, SAH cost\n";
        writeParameterMarkdown(std::cout, sweep, points);
        if (!options.outDir.empty()) {
            writeParameterCsv(outPath("parameters.csv"), points);
            writeParameterSvgs(outPath("pareto-build-trace.svg"), outPath("sah-vs-trace.svg"), sweep, points);
        }
    }
    if (!options.skipRender) {
        RenderRaceOptions race = options.renderRace;
        race.modelsDir = options.modelsDir;
        if (options.quick) race = quickRenderRace(race);
        RenderRaceResult result = runRenderRace(race);
        std::cout << "\n## The renderer against POV-Ray\n\n";
        writeRenderRaceMarkdown(std::cout, result);
    }
    if (!options.outDir.empty()) std::cout << "\nCSV and SVG files are in " << options.outDir << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    CLI::App app{"rtlab bench: accelerators against Embree, and run time against error (docs/performance.md)"};
    app.add_option("--scenes", options.scenes,
                   "Scenes: bunny, engine, sphereflake, randsoup, stadium or glTF paths (default: bunny engine sphereflake; "
                   "--quick: bunny)")
        ->delimiter(',');
    app.add_option("--systems", options.systems, "Only these rows, e.g. rtlab:bvh-buckets:12,embree:high")
        ->delimiter(',')
        ->check(CLI::IsMember(allSystemLabels()));
    app.add_option("--accel", options.accelerators,
                   "Only this rtlab accelerator (repeatable), as in render and hits: a row's name above or any "
                   "setting of one, e.g. fastbvh:bins=8");
    app.add_option("--max-leaf", options.maxLeaf, "Largest leaf of every rtlab BVH row")
        ->check(CLI::Range(1, 65535))
        ->capture_default_str();
    app.add_option("--out", options.outDir, "Write results.csv, the other CSVs and the SVG plots here");
    app.add_option("--models", options.modelsDir, "Where scripts/fetch-models put bunny.gltf");
    app.add_flag("--quick", options.quick, "A fast smoke run for CI: every 16th ray, one pass, small images");
    app.add_flag("--check-reference", options.checkReferenceHits,
                 "Only compare Embree's hits with the reference page and rtlab's with Embree's (exit 1 if off)");
    app.add_option("--check-accel", options.checkAccelerator, "The rtlab accelerator --check-reference compares");
    app.add_flag("--no-throughput", options.skipThroughput, "Skip the throughput table");
    app.add_flag("--no-race", options.skipRace, "Skip the alternating race of the fast path against Embree (issue 26's targets)");
    app.add_option("--rounds", options.race.rounds, "Rounds of that race (at least 5)")
        ->check(CLI::Range(5, 1000))
        ->capture_default_str();
    app.add_option("--race-accel", options.race.accelerator,
                   "The rtlab accelerator of the race (default: the fastest, " + defaultRenderAccelerator() + ")");
    app.add_option("--embree-isa", options.race.embreeIsa,
                   "Hold Embree's kernels in that race to this instruction set (by default it takes the best this "
                   "CPU runs, AVX-512 where there is one)")
        ->check(CLI::IsMember({"sse2", "sse4.2", "avx", "avx2", "avx512"}));
    app.add_flag("--no-convergence", options.skipConvergence, "Skip image error against samples per pixel");
    app.add_flag("--no-parameters", options.skipParameters, "Skip the bucket count / leaf size sweep");
    app.add_flag("--no-estimators", options.skipEstimators, "Skip the estimators of direct light (a6) against each other");
    app.add_flag("--no-render", options.skipRender, "Skip the render against POV-Ray's (and its time beyond tracing)");
    app.add_option("--render-scene", options.renderRace.scene, "Scene of the render against POV-Ray")->capture_default_str();
    app.add_option("--render-size", options.renderRace.size, "Width and height of that render (--quick: 196)")
        ->check(CLI::Range(1, 1 << 15))
        ->capture_default_str();
    app.add_option("--convergence-scene", options.convergenceScene, "Scene of the samples-per-pixel study");
    app.add_option("--parameter-scene", options.parameterScene, "Scene of the parameter sweep");
    app.add_option("--estimator-scene", options.estimatorScene, "Scene of the estimator comparison (area lights)")
        ->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        return runBench(options);
    } catch (const std::exception& e) {
        std::cerr << "rtlab bench: " << e.what() << "\n";
        return 1;
    }
}
