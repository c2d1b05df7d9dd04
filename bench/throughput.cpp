#include "bench/throughput.h"

#include "bench/bench_scenes.h"
#include "bench/embree_system.h"
#include "bench/rtlab_system.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/primitive_set.h"
#include "framework/core/error.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

namespace rtlab::bench {

namespace {

constexpr size_t kBruteForceRayStride = 64;

std::vector<BenchRay> benchRays(RayKind kind, const Bounds3f& bounds, size_t stride) {
    std::vector<Ray> rays = makeBenchmarkRays(kind, bounds);
    std::vector<BenchRay> out;
    out.reserve(rays.size() / stride + 1);
    for (size_t i = 0; i < rays.size(); i += stride) out.push_back({rays[i].origin, rays[i].direction});
    return out;
}

struct SceneRays {
    RayKind kind;
    std::vector<BenchRay> rays;
    std::vector<TraceResult> embreeMedium;  // the reference hits
    double embreeMediumMrays[3] = {0, 0, 0};  // by thread count
};

std::unique_ptr<BenchSystem> makeSystem(const std::string& label, const Scene& scene, const PrimitiveSet& primitives,
                                        int maxLeaf) {
    if (label == "embree:medium") return std::make_unique<EmbreeSystem>(scene, EmbreeQuality::Medium);
    if (label == "embree:high") return std::make_unique<EmbreeSystem>(scene, EmbreeQuality::High);
    return std::make_unique<RtlabSystem>(primitives, withMaxLeaf(label.substr(6), maxLeaf));  // after "rtlab:"
}

bool selected(const ThroughputOptions& options, const std::string& label) {
    return options.systems.empty() ||
           std::find(options.systems.begin(), options.systems.end(), label) != options.systems.end();
}

}  // namespace

std::vector<std::string> allSystemLabels() {
    std::vector<std::string> labels;
    // Every structure's own rows (the accelerator registry): the a1/a2 BVHs as students traverse
    // them, the grid's C sweep, then the fast paths' wide traversals of the SAH trees.
    for (const AcceleratorType* type : acceleratorTypes())
        for (const std::string& name : type->benchRows) labels.push_back("rtlab:" + name);
    labels.push_back("embree:medium");
    labels.push_back("embree:high");
    return labels;
}

bool resultsDiffer(const TraceResult& result, const TraceResult& reference) {
    bool hit = result.prim != kNoHit, referenceHit = reference.prim != kNoHit;
    if (hit != referenceHit) return true;
    return hit && !(std::fabs(result.t - reference.t) <= 1e-4f * std::max(1.0f, reference.t));
}

std::vector<ThroughputRecord> runThroughput(const ThroughputOptions& options) {
    std::vector<ThroughputRecord> records;
    for (const std::string& sceneName : options.scenes) {
        std::cerr << "bench: loading " << sceneName << "\n";
        Scene scene = loadBenchScene(sceneName, options.modelsDir);
        if (!scene.spheres.empty())
            throw Error(sceneName + ": the throughput benchmark takes triangle meshes only (Embree gets no spheres)");
        PrimitiveSet primitives(scene);
        Bounds3f bounds = benchRayBounds(sceneName, scene);
        int repeats = options.buildRepeats.value_or(buildRepeats(scene.triangleCount()));
        std::vector<SceneRays> raySets;
        for (RayKind kind : {RayKind::Primary, RayKind::Incoherent})
            raySets.push_back({kind, benchRays(kind, bounds, options.rayStride), {}, {}});

        // Embree MEDIUM first: every other row is compared with its hits and its speed.
        // Rows named with settings of their own (--accel fastbvh:leaf=4) come last.
        std::vector<std::string> labels = allSystemLabels();
        for (const std::string& label : options.systems)
            if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
        std::stable_partition(labels.begin(), labels.end(), [](const std::string& l) { return l == "embree:medium"; });
        for (const std::string& label : labels) {
            bool isReference = label == "embree:medium";
            if (!isReference && !selected(options, label)) continue;
            std::string load = loadAverage();
            // A row of this scene and system; the caller fills in what was measured.
            auto newRecord = [&](RayKind rays, int threads) {
                ThroughputRecord r;
                r.scene = sceneName;
                r.triangles = scene.triangleCount();
                r.system = label;
                r.rays = rays;
                r.threads = threads;
                r.loadAverage = load;
                return r;
            };
            auto skip = [&](const std::string& note) {
                for (const SceneRays& set : raySets)
                    for (int threads : {1, 2}) {
                        ThroughputRecord r = newRecord(set.kind, threads);
                        r.measured = false;
                        r.note = note;
                        records.push_back(r);
                    }
                std::cerr << "bench: " << sceneName << " " << label << ": " << note << "\n";
            };
            if (label == "rtlab:brute" && scene.triangleCount() > options.bruteForceLimit) {
                skip("skipped: brute force above " + std::to_string(options.bruteForceLimit) + " triangles");
                continue;
            }
            std::unique_ptr<BenchSystem> system = makeSystem(label, scene, primitives, options.maxLeaf);
            try {
                std::cerr << "bench: " << sceneName << " " << label << ": building" << std::flush;
                double build1 = medianBuildMs(*system, 1, repeats, /*pinToOneCpu=*/true);
                // Most of rtlab's builders are single-threaded: a 2T build is the same computation.
                bool parallelBuild = system->buildsInParallel();
                double build2 = parallelBuild ? medianBuildMs(*system, 2, repeats, false) : build1;
                system->build(2);
                std::optional<double> references = system->referencesPerTriangle();
                std::cerr << " " << build1 << " ms; tracing" << std::flush;
                // Brute force tests every triangle for every ray: it gets every 64th ray of the
                // set and one pass, and its mismatches are counted on that subset.
                bool brute = label == "rtlab:brute";
                size_t stride = brute ? kBruteForceRayStride : 1;
                TraceProtocol protocol = brute ? TraceProtocol{0.0, 1, 1, 0.0} : options.protocol;
                for (SceneRays& set : raySets) {
                    std::vector<BenchRay> rays;
                    std::vector<TraceResult> reference;
                    for (size_t i = 0; i < set.rays.size(); i += stride) {
                        rays.push_back(set.rays[i]);
                        if (!set.embreeMedium.empty()) reference.push_back(set.embreeMedium[i]);
                    }
                    std::vector<TraceResult> results;
                    for (int threads : {1, 2}) {
                        TraceTiming timing = timeTrace(*system, rays, threads, protocol, results);
                        if (isReference) {
                            set.embreeMediumMrays[threads] = timing.bestMraysPerSecond;
                            if (threads == 1) set.embreeMedium = results;
                        }
                        ThroughputRecord r = newRecord(set.kind, threads);
                        r.buildMs = threads == 1 ? build1 : build2;
                        r.parallelBuild = parallelBuild;
                        r.mraysPerSecond = timing.bestMraysPerSecond;
                        r.ratioToEmbreeMedium = set.embreeMediumMrays[threads] > 0.0
                                                    ? timing.bestMraysPerSecond / set.embreeMediumMrays[threads]
                                                    : 0.0;
                        r.sahCost = system->sahCost();
                        if (system->countsWork() && timing.stats.rays > 0) {
                            r.nodeVisitsPerRay = static_cast<double>(timing.stats.nodeVisits) / timing.stats.rays;
                            r.primitiveTestsPerRay =
                                static_cast<double>(timing.stats.primitiveTests) / timing.stats.rays;
                            if (timing.stats.cellSteps > 0)
                                r.cellStepsPerRay = static_cast<double>(timing.stats.cellSteps) / timing.stats.rays;
                            if (timing.stats.planeSteps > 0)
                                r.planeStepsPerRay = static_cast<double>(timing.stats.planeSteps) / timing.stats.rays;
                        }
                        r.bytesPerTriangle = system->bytesPerTriangle();
                        r.referencesPerTriangle = references;
                        if (!isReference && !reference.empty()) {
                            uint64_t mismatches = 0;
                            for (size_t i = 0; i < results.size(); ++i)
                                mismatches += resultsDiffer(results[i], reference[i]);
                            r.mismatches = mismatches;
                        }
                        if (brute) r.note = "every " + std::to_string(stride) + "th ray, one pass";
                        for (const TraceResult& result : results)
                            if (result.prim != kNoHit) {
                                ++r.hits;
                                r.sumT += result.t;
                            }
                        records.push_back(r);
                        std::cerr << " " << rayKindName(set.kind) << "@" << threads << "T "
                                  << timing.bestMraysPerSecond << std::flush;
                    }
                }
                std::cerr << " Mrays/s\n";
            } catch (const NotImplemented& e) {
                std::cerr << "\n";
                skip(std::string("not started (") + e.what() + ")");
            }
        }
    }
    return records;
}

}  // namespace rtlab::bench
