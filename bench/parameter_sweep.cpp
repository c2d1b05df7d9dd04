#include "bench/parameter_sweep.h"

#include "bench/bench_scenes.h"
#include "bench/rtlab_system.h"
#include "bench/svg_plot.h"
#include "framework/accel/primitive_set.h"
#include "framework/core/error.h"
#include "framework/scene/benchmark_rays.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace rtlab::bench {

namespace {

// "B12" for bucketed SAH, "sweep" for the full sweep. (Appending, not "B" + std::to_string(...),
// which trips GCC 12's false -Wrestrict warning.)
std::string bucketLabel(const ParameterPoint& p) {
    if (p.buckets == 0) return "sweep";
    std::string label = "B";
    label += std::to_string(p.buckets);
    return label;
}

std::string shortName(const ParameterPoint& p) { return bucketLabel(p) + " L" + std::to_string(p.maxLeaf); }

void markParetoFront(std::vector<ParameterPoint>& points) {
    for (ParameterPoint& p : points) {
        p.pareto = std::none_of(points.begin(), points.end(), [&](const ParameterPoint& q) {
            return q.buildMs <= p.buildMs && q.traceMs <= p.traceMs && (q.buildMs < p.buildMs || q.traceMs < p.traceMs);
        });
    }
}

const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2"};

}  // namespace

ParameterSweepOptions quickParameterSweep(ParameterSweepOptions options) {
    options.buckets = {4, 12};
    options.maxLeaf = {2, 4};
    options.fullSweep = false;
    options.rayStride = 16;
    options.protocol = TraceProtocol{0.0, 1, 1, 0.0};
    options.buildRepeats = 1;
    return options;
}

std::vector<ParameterPoint> runParameterSweep(const ParameterSweepOptions& options) {
    Scene scene = loadBenchScene(options.scene, options.modelsDir);
    PrimitiveSet primitives(scene);
    std::vector<BenchRay> rays[2];
    size_t fullCount[2];
    for (RayKind kind : {RayKind::Primary, RayKind::Incoherent}) {
        std::vector<Ray> all = makeBenchmarkRays(kind, scene.bounds());
        fullCount[static_cast<int>(kind)] = all.size();
        for (size_t i = 0; i < all.size(); i += options.rayStride)
            rays[static_cast<int>(kind)].push_back({all[i].origin, all[i].direction});
    }
    std::vector<std::pair<std::string, int>> rows;  // accelerator name, maxLeaf
    for (int leaf : options.maxLeaf) {
        for (int b : options.buckets) rows.emplace_back("bvh-buckets:" + std::to_string(b), leaf);
        if (options.fullSweep) rows.emplace_back("bvh-sah", leaf);
    }
    std::vector<ParameterPoint> points;
    std::cerr << "bench: parameter sweep on " << options.scene << ":";
    for (const auto& [name, leaf] : rows) {
        RtlabSystem system(primitives, withMaxLeaf(name, leaf));
        ParameterPoint p;
        p.accelerator = name;
        p.buckets = name.starts_with("bvh-buckets:") ? std::stoi(name.substr(12)) : 0;
        p.maxLeaf = leaf;
        p.buildMs = medianBuildMs(system, 1, options.buildRepeats, /*pinToOneCpu=*/true);
        system.build(1);
        p.sahCost = system.sahCost().value_or(0.0);
        std::vector<TraceResult> results;
        for (int kind = 0; kind < 2; ++kind) {
            TraceTiming timing = timeTrace(system, rays[kind], 1, options.protocol, results);
            p.traceMs += static_cast<double>(fullCount[kind]) / timing.bestMraysPerSecond * 1e-3;
        }
        points.push_back(p);
        std::cerr << " " << shortName(p) << std::flush;
    }
    std::cerr << "\n";
    markParetoFront(points);
    return points;
}

void writeParameterMarkdown(std::ostream& out, const ParameterSweepOptions& options,
                            const std::vector<ParameterPoint>& points) {
    out << "\n" << options.scene << "; single thread; trace ms = primary + incoherent sets (2 x 2^20 rays, measured on "
        << "every " << options.rayStride << "th ray); load average " << loadAverage() << " at the end\n\n"
        << "| accelerator | maxLeaf | build ms | trace ms | SAH cost | Pareto |\n|---|--:|--:|--:|--:|:-:|\n";
    for (const ParameterPoint& p : points) {
        char line[160];
        std::snprintf(line, sizeof line, "| %s | %d | %.1f | %.0f | %.2f | %s |\n", p.accelerator.c_str(), p.maxLeaf,
                      p.buildMs, p.traceMs, p.sahCost, p.pareto ? "yes" : "");
        out << line;
    }
}

void writeParameterCsv(const std::string& path, const std::vector<ParameterPoint>& points) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot open for writing");
    out << "accelerator,buckets,max_leaf,build_ms,trace_ms,sah_cost,pareto\n";
    for (const ParameterPoint& p : points)
        out << p.accelerator << ',' << p.buckets << ',' << p.maxLeaf << ',' << p.buildMs << ',' << p.traceMs << ','
            << p.sahCost << ',' << (p.pareto ? 1 : 0) << '\n';
    if (!out.flush()) throw Error(path + ": write failed");
}

void writeParameterSvgs(const std::string& paretoPath, const std::string& sahPath, const ParameterSweepOptions& options,
                        const std::vector<ParameterPoint>& points) {
    // One series per leaf size, so the effect of B reads along each colour.
    auto byLeaf = [&](bool sahOnX) {
        std::vector<PlotSeries> series;
        size_t colour = 0;
        for (int leaf : options.maxLeaf) {
            PlotSeries s{"maxLeaf " + std::to_string(leaf), kPalette[colour++ % std::size(kPalette)], {}, false, true, false};
            for (const ParameterPoint& p : points)
                if (p.maxLeaf == leaf)
                    s.points.push_back({sahOnX ? p.sahCost : p.buildMs, p.traceMs, bucketLabel(p)});
            series.push_back(s);
        }
        return series;
    };
    Plot pareto;
    pareto.title = "SAH BVH parameters: build against trace time (" + options.scene + ")";
    pareto.xLabel = "build ms (1 thread)";
    pareto.yLabel = "trace ms, 2 x 2^20 rays (1 thread)";
    pareto.series = byLeaf(false);
    PlotSeries front{"Pareto front", "#000000", {}, true, false, true};
    for (const ParameterPoint& p : points)
        if (p.pareto) front.points.push_back({p.buildMs, p.traceMs, ""});
    std::sort(front.points.begin(), front.points.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
    pareto.series.push_back(front);
    writeSvg(paretoPath, pareto);

    Plot sah;
    sah.title = "SAH cost against trace time (" + options.scene + ")";
    sah.xLabel = "SAH cost (C_trav = C_isect = 1)";
    sah.yLabel = "trace ms, 2 x 2^20 rays (1 thread)";
    sah.series = byLeaf(true);
    writeSvg(sahPath, sah);
}

}  // namespace rtlab::bench
