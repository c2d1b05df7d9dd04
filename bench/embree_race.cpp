#include "bench/embree_race.h"

#include "bench/bench_scenes.h"
#include "bench/embree_system.h"
#include "bench/report.h"
#include "bench/rtlab_system.h"
#include "bench/shadow_rays.h"
#include "bench/throughput.h"
#include "bench/timing.h"
#include "fast/wide_bvh_dispatch.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/primitive_set.h"
#include "framework/core/error.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <thread>

namespace rtlab::bench {
namespace {

constexpr int kMinRounds = 5;
constexpr double kRatioTarget = 1.0;          // ours at least as fast as Embree MEDIUM
constexpr double kBytesPerTriangleTarget = 80.0;
constexpr const char* kBuildTargetScene = "sphereflake";
constexpr int kBuildTargetThreads = 2;
constexpr std::chrono::milliseconds kPauseBeforeBuild{50};

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<BenchRay> benchRays(RayKind kind, const Bounds3f& bounds, size_t stride) {
    std::vector<Ray> rays = makeBenchmarkRays(kind, bounds);
    std::vector<BenchRay> out;
    for (size_t i = 0; i < rays.size(); i += stride) out.push_back({rays[i].origin, rays[i].direction});
    return out;
}

// Runs one side's pass (true: ours) and returns its seconds.
using Pass = std::function<double(bool ours)>;

// Both sides take turns, the first one alternating from round to round; in a round a side passes
// until roundSeconds have gone and keeps its best throughput.
RaceRow raceQueries(RaceRow row, const RaceOptions& options, const Pass& pass) {
    pass(true);  // warm-up: caches, pages, the thread's first touch of the results
    pass(false);
    for (int round = 0; round < options.rounds; ++round) {
        double best[2] = {0.0, 0.0};  // [0]: ours
        for (int turn = 0; turn < 2; ++turn) {
            bool ours = (turn == 0) == (round % 2 == 0);
            double total = 0.0;
            do {
                double seconds = pass(ours);
                total += seconds;
                if (seconds > 0.0) best[ours ? 0 : 1] = std::max(best[ours ? 0 : 1], row.queries / seconds * 1e-6);
            } while (total < options.roundSeconds);
        }
        row.ours.push_back(best[0]);
        row.embree.push_back(best[1]);
    }
    return row;
}

RaceRow raceBuilds(const std::string& scene, int threads, const RaceOptions& options, BenchSystem& ours,
                   BenchSystem& embree) {
    auto build = [threads](BenchSystem& system) {
        // Embree's worker threads spin for a while after its build before they sleep; a pause
        // before every build keeps them from competing with the build that comes next.
        std::this_thread::sleep_for(kPauseBeforeBuild);
        std::optional<PinToCpu0> pin;  // one thread: the process on CPU 0, so rtlab's builder sees one CPU
        if (threads == 1) pin.emplace();
        return system.build(threads);
    };
    build(ours);  // warm-up: Embree's device and thread pool, first pages
    build(embree);
    RaceRow row{scene, "build", threads, {}, {}, std::nullopt, 0};
    for (int round = 0; round < options.rounds; ++round) {
        if (round % 2 == 0) {
            row.ours.push_back(build(ours));
            row.embree.push_back(build(embree));
        } else {
            row.embree.push_back(build(embree));
            row.ours.push_back(build(ours));
        }
    }
    return row;
}

std::string spread(const RaceRow& row) {
    std::vector<double> r = row.ratios();
    auto [low, high] = std::minmax_element(r.begin(), r.end());
    return format("%.2f", *low) + "–" + format("%.2f", *high);
}

std::string figure(const RaceRow& row, double value) {
    return row.kind == "build" ? shortNumber(value) + " ms" : format("%.2f", value);
}

}  // namespace

std::vector<double> RaceRow::ratios() const {
    std::vector<double> r;
    for (size_t i = 0; i < ours.size() && i < embree.size(); ++i)
        r.push_back(kind == "build" ? embree[i] / ours[i] : ours[i] / embree[i]);
    return r;
}

double RaceRow::medianRatio() const { return median(ratios()); }

RaceOptions quickRace(RaceOptions options) {
    if (options.scenes.empty()) options.scenes = {"bunny"};
    options.rounds = kMinRounds;
    options.roundSeconds = 0.0;
    options.rayStride = 16;
    return options;
}

RaceResult runRace(const RaceOptions& options) {
    if (options.rounds < kMinRounds)
        throw Error("the race against Embree needs at least " + std::to_string(kMinRounds) + " rounds");
    RaceResult result;
    result.options = options;
    result.accelerator = options.accelerator.empty() ? defaultRenderAccelerator() : options.accelerator;
    result.loadAtStart = loadAverage();
    std::vector<std::string> scenes =
        options.scenes.empty() ? std::vector<std::string>{"bunny", "engine", "sphereflake"} : options.scenes;
    for (const std::string& sceneName : scenes) {
        std::cerr << "bench: race on " << sceneName << std::flush;
        Scene scene = loadBenchScene(sceneName, options.modelsDir);
        if (!scene.spheres.empty())
            throw Error(sceneName + ": the race against Embree takes triangle meshes only (Embree gets no spheres)");
        PrimitiveSet primitives(scene);
        Bounds3f bounds = benchRayBounds(sceneName, scene);
        AcceleratorSpec spec;
        spec.name = result.accelerator;
        RtlabSystem ours(primitives, spec);
        EmbreeSystem embree(scene, EmbreeQuality::Medium, options.embreeIsa);

        for (int threads : {1, 2}) result.rows.push_back(raceBuilds(sceneName, threads, options, ours, embree));
        result.memory.push_back({sceneName, ours.bytesPerTriangle(), embree.bytesPerTriangle()});
        std::cerr << ": built" << std::flush;

        std::vector<BenchRay> primary = benchRays(RayKind::Primary, bounds, options.rayStride);
        std::vector<BenchRay> incoherent = benchRays(RayKind::Incoherent, bounds, options.rayStride);
        std::vector<TraceResult> embreePrimary(primary.size());
        TraversalStats unused;
        embree.trace(primary, embreePrimary.data(), unused);
        std::vector<BenchSegment> shadow = makeShadowRays(primary, embreePrimary, bounds);

        for (int threads : {1, 2}) {
            for (const std::vector<BenchRay>* rays : {&primary, &incoherent}) {
                std::vector<TraceResult> results[2] = {std::vector<TraceResult>(rays->size()),
                                                       std::vector<TraceResult>(rays->size())};
                Pass pass = [&](bool isOurs) {
                    const BenchSystem& system = isOurs ? static_cast<const BenchSystem&>(ours) : embree;
                    TraceResult* out = results[isOurs ? 0 : 1].data();
                    TraversalStats stats;
                    return timedPass(
                        rays->size(), threads,
                        [&](size_t begin, size_t count, TraversalStats& s) {
                            system.trace(std::span(*rays).subspan(begin, count), out + begin, s);
                        },
                        stats);
                };
                RaceRow row{sceneName, rays == &primary ? "primary" : "incoherent", threads, {}, {}, 0, rays->size()};
                row = raceQueries(row, options, pass);
                uint64_t mismatches = 0;
                for (size_t i = 0; i < rays->size(); ++i) mismatches += resultsDiffer(results[0][i], results[1][i]);
                row.mismatches = mismatches;
                result.rows.push_back(row);
                std::cerr << " " << row.kind << "@" << threads << "T " << format("%.2f", row.medianRatio()) << std::flush;
            }
            std::vector<uint8_t> blocked[2] = {std::vector<uint8_t>(shadow.size()), std::vector<uint8_t>(shadow.size())};
            Pass pass = [&](bool isOurs) {
                const BenchSystem& system = isOurs ? static_cast<const BenchSystem&>(ours) : embree;
                uint8_t* out = blocked[isOurs ? 0 : 1].data();
                TraversalStats stats;
                return timedPass(
                    shadow.size(), threads,
                    [&](size_t begin, size_t count, TraversalStats& s) {
                        system.occluded(std::span(shadow).subspan(begin, count), out + begin, s);
                    },
                    stats);
            };
            RaceRow row = raceQueries({sceneName, "shadow", threads, {}, {}, 0, shadow.size()}, options, pass);
            uint64_t mismatches = 0;
            for (size_t i = 0; i < shadow.size(); ++i) mismatches += blocked[0][i] != blocked[1][i];
            row.mismatches = mismatches;
            result.rows.push_back(row);
            std::cerr << " shadow@" << threads << "T " << format("%.2f", row.medianRatio()) << std::flush;
        }
        std::cerr << "\n";
    }
    result.loadAtEnd = loadAverage();
    return result;
}

void writeRaceMarkdown(std::ostream& out, const RaceResult& result) {
    const RaceOptions& o = result.options;
    // Which copy of fast/'s wide traversal ran (fast/wide_bvh_dispatch.h): Embree picks its ISA
    // at run time, and a portable build does too.
    out << "rtlab:" << result.accelerator << (usesAvx2Copy() ? " (its AVX2 copy)" : "") << " against embree:medium"
        << (o.embreeIsa.empty() ? "" : " (its kernels held to " + o.embreeIsa + ")") << ", " << o.rounds
        << " alternating rounds" << (o.rayStride > 1 ? ", every " + std::to_string(o.rayStride) + "th ray" : "")
        << "; load average " << result.loadAtStart << " at the start, " << result.loadAtEnd << " at the end.\n\n"
        << "| scene | query | threads | ours (median) | Embree (median) | ratio: median | min–max | mismatches |\n"
        << "|---|---|--:|--:|--:|--:|--:|--:|\n";
    for (const RaceRow& row : result.rows)
        out << "| " << row.scene << " | " << row.kind << " | " << row.threads << " | " << figure(row, median(row.ours))
            << " | " << figure(row, median(row.embree)) << " | " << format("%.2f", row.medianRatio()) << " | "
            << spread(row) << " | "
            << (row.mismatches ? std::to_string(*row.mismatches) + " of " + std::to_string(row.queries) : "–")
            << " |\n";
    out << "\nQueries: Mrays/s, the best pass of each side in each round; builds: ms (1T pinned to one CPU). Ratio: "
           "ours / Embree's throughput, Embree's / our build time (at least 1: ours at least as fast), per round.\n\n"
        << "| scene | ours bytes/tri | Embree bytes/tri |\n|---|--:|--:|\n";
    for (const RaceMemory& m : result.memory)
        out << "| " << m.scene << " | " << format("%.1f", m.oursBytesPerTriangle) << " | "
            << format("%.1f", m.embreeBytesPerTriangle) << " |\n";

    out << "\nTargets (issue 26), one line each:\n\n";
    for (const RaceRow& row : result.rows) {
        bool throughput = row.kind != "build";
        if (!throughput && (row.scene != kBuildTargetScene || row.threads != kBuildTargetThreads)) continue;
        double ratio = row.medianRatio();
        out << "- " << row.scene << " " << row.kind << " " << row.threads << "T: "
            << (throughput ? "ours / Embree MEDIUM " : "Embree MEDIUM's time / ours ") << format("%.2f", ratio) << "× ("
            << spread(row) << " over " << row.ratios().size() << " rounds), target ≥ " << format("%.1f", kRatioTarget)
            << "×: " << verdict(ratio >= kRatioTarget) << "\n";
    }
    for (const RaceMemory& m : result.memory)
        out << "- " << m.scene << " memory: " << format("%.1f", m.oursBytesPerTriangle) << " bytes per triangle, target ≤ "
            << format("%.0f", kBytesPerTriangleTarget) << ": " << verdict(m.oursBytesPerTriangle <= kBytesPerTriangleTarget)
            << "\n";
}

void writeRaceCsv(const std::string& path, const RaceResult& result) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot open for writing");
    out << "scene,kind,threads,round,ours,embree,ratio\n";
    for (const RaceRow& row : result.rows) {
        std::vector<double> ratios = row.ratios();
        for (size_t i = 0; i < ratios.size(); ++i)
            out << row.scene << ',' << row.kind << ',' << row.threads << ',' << i << ',' << row.ours[i] << ','
                << row.embree[i] << ',' << ratios[i] << '\n';
    }
    for (const RaceMemory& m : result.memory)
        out << m.scene << ",bytes_per_triangle,,," << m.oursBytesPerTriangle << ',' << m.embreeBytesPerTriangle << ",\n";
    if (!out.flush()) throw Error(path + ": write failed");
}

}  // namespace rtlab::bench
