#include "bench/convergence.h"

#include "bench/bench_scenes.h"
#include "bench/svg_plot.h"
#include "bench/timing.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/primitive_set.h"
#include "framework/core/error.h"
#include "framework/verification/image_compare.h"
#include "framework/render/renderer.h"
#include "framework/scene/benchmark_rays.h"
#include "framework/scene/emitters.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace rtlab::bench {

namespace {

// The renderer at spp samples per pixel; `seed` keeps the reference's samples apart from the
// measured ones.
Image render(const Scene& scene, const Camera& camera, const Accelerator& accelerator, const ConvergenceOptions& options,
             LightSampling sampling, int spp, uint64_t seed) {
    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.threads = options.threads;
    settings.progress = false;
    settings.samplesPerPixel = spp;
    settings.seed = seed;
    settings.lightSampling = sampling;
    return Renderer(scene, camera, accelerator).render(settings).colour;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// 1 / (MSE x seconds) at the largest sample count of each sampling: the inverse of the work
// needed for a given error. The seconds are that count times the series' mean time per sample
// (all its renders together), steadier on a shared machine than one render's time.
std::vector<std::pair<LightSampling, double>> efficiencies(const ConvergenceResult& result) {
    std::vector<std::pair<LightSampling, double>> out;
    for (LightSampling sampling : result.options.samplings) {
        const ConvergencePoint* last = nullptr;
        double seconds = 0.0, samples = 0.0;
        for (const ConvergencePoint& p : result.points)
            if (p.sampling == sampling) {
                last = &p;
                seconds += p.seconds;
                samples += p.spp;
            }
        if (last) out.emplace_back(sampling, 1.0 / (last->rmse * last->rmse * last->spp * seconds / samples));
    }
    return out;
}

const char* colourOf(size_t series) {
    static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"};
    return colours[series % 5];
}

}  // namespace

ConvergenceOptions quickConvergence(ConvergenceOptions options) {
    options.width = options.height = 48;
    options.referenceSpp = 64;
    options.spp = {1, 4, 16};
    return options;
}

ConvergenceOptions estimatorComparison(const std::string& scenePath, bool quick) {
    ConvergenceOptions options;
    options.scene = scenePath;
    options.width = 96;
    options.height = 72;
    options.referenceSpp = 4096;
    options.samplings = {LightSampling::SolidAngle, LightSampling::Area, LightSampling::Cosine, LightSampling::Hemisphere};
    if (quick) {
        options = quickConvergence(options);
        options.referenceSpp = 256;
    }
    return options;
}

ConvergenceResult runConvergence(const ConvergenceOptions& options) {
    for (int spp : options.spp)
        if (spp < 1 || (spp & (spp - 1)) != 0) throw Error("samples per pixel must be powers of two, not " + std::to_string(spp));
    if (options.samplings.empty()) throw Error("the convergence study needs a light sampling");
    Scene scene = loadBenchScene(options.scene, options.modelsDir);
    if (scene.lights.empty() && findEmitters(scene).empty())
        throw Error(options.scene + ": the samples-per-pixel study needs a scene with a light");
    Camera camera = scene.cameras.empty() ? BenchmarkView(scene.bounds()).camera() : scene.cameras.front();
    PrimitiveSet primitives(scene);
    AcceleratorSpec spec;
    spec.name = options.accelerator;
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
    accelerator->build(primitives);

    ConvergenceResult result;
    result.options = options;
    result.loadAverage = loadAverage();
    std::cerr << "bench: convergence on " << options.scene << ": reference at " << options.referenceSpp << " spp" << std::flush;
    auto start = std::chrono::steady_clock::now();
    Image reference = render(scene, camera, *accelerator, options, options.samplings.front(), options.referenceSpp, 1);
    result.referenceSeconds = seconds(start);
    double total = 0.0;
    for (float v : reference.pixels) total += v;
    result.referenceMean = total / static_cast<double>(reference.pixels.size());

    for (LightSampling sampling : options.samplings) {
        if (options.samplings.size() > 1) std::cerr << "; " << lightSamplingName(sampling);
        for (int spp : options.spp) {
            std::cerr << ", " << spp << std::flush;
            auto begin = std::chrono::steady_clock::now();
            Image image = render(scene, camera, *accelerator, options, sampling, spp, 2);
            ConvergencePoint point;
            point.sampling = sampling;
            point.spp = spp;
            point.seconds = seconds(begin);
            point.rmse = compareImages(image, reference).rmse;
            point.relativeRmse = result.referenceMean > 0.0 ? point.rmse / result.referenceMean : 0.0;
            result.points.push_back(point);
        }
    }
    std::cerr << " spp\n";
    return result;
}

void writeConvergenceMarkdown(std::ostream& out, const ConvergenceResult& result) {
    const ConvergenceOptions& o = result.options;
    bool several = o.samplings.size() > 1;
    out << "\n" << o.scene << ", " << o.width << "x" << o.height << ", rtlab:" << o.accelerator << ", " << o.threads
        << " threads, reference " << o.referenceSpp << " spp" << (several ? std::string(" by ") + lightSamplingName(o.samplings.front()) : "")
        << " (" << result.referenceSeconds << " s); load average " << result.loadAverage << "\n\n"
        << (several ? "| light sampling " : "") << "| spp | render s | RMSE | RMSE / mean |\n"
        << (several ? "|---" : "") << "|--:|--:|--:|--:|\n";
    for (const ConvergencePoint& p : result.points) {
        char line[160];
        std::snprintf(line, sizeof line, "| %d | %.3f | %.3g | %.3g |\n", p.spp, p.seconds, p.rmse, p.relativeRmse);
        out << (several ? std::string("| ") + lightSamplingName(p.sampling) + " " : "") << line;
    }
    for (LightSampling sampling : o.samplings) {
        std::vector<const ConvergencePoint*> series;
        for (const ConvergencePoint& p : result.points)
            if (p.sampling == sampling) series.push_back(&p);
        if (series.size() < 2) continue;
        const ConvergencePoint& a = *series.front();
        const ConvergencePoint& b = *series.back();
        out << "\n" << (several ? std::string(lightSamplingName(sampling)) + ": e" : "E") << "rror slope from " << a.spp << " to "
            << b.spp << " spp: " << std::log(b.rmse / a.rmse) / std::log(static_cast<double>(b.spp) / a.spp)
            << " (plain Monte Carlo: -0.5; stratified samples converge faster where the integrand is smooth).\n";
    }
    if (!several) return;
    auto eff = efficiencies(result);
    double best = 0.0;
    for (const auto& [sampling, e] : eff) best = std::max(best, e);
    out << "\nEfficiency 1 / (MSE x render time) at " << o.spp.back() << " spp (the time from the series' mean time per "
        << "sample), relative to the best:\n\n"
        << "| light sampling | efficiency | relative |\n|---|--:|--:|\n";
    for (const auto& [sampling, e] : eff) {
        char line[128];
        std::snprintf(line, sizeof line, "| %s | %.4g | %.3g |\n", lightSamplingName(sampling), e, e / best);
        out << line;
    }
}

void writeConvergenceCsv(const std::string& path, const ConvergenceResult& result) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot open for writing");
    out << "scene,accelerator,width,height,reference_spp,light_sampling,spp,seconds,rmse,relative_rmse\n";
    for (const ConvergencePoint& p : result.points)
        out << result.options.scene << ",rtlab:" << result.options.accelerator << ',' << result.options.width << ','
            << result.options.height << ',' << result.options.referenceSpp << ',' << lightSamplingName(p.sampling) << ','
            << p.spp << ',' << p.seconds << ',' << p.rmse << ',' << p.relativeRmse << '\n';
    if (!out.flush()) throw Error(path + ": write failed");
}

void writeConvergenceSvg(const std::string& svgPath, const ConvergenceResult& result) {
    if (result.points.empty()) return;
    const ConvergencePoint& first = result.points.front();
    bool several = result.options.samplings.size() > 1;
    for (bool againstTime : {true, false}) {
        Plot plot;
        plot.title = "Image error against " + std::string(againstTime ? "render time" : "samples per pixel") + " (" +
                     result.options.scene + ")";
        plot.xLabel = againstTime ? "render time [s]" : "samples per pixel";
        plot.yLabel = "RMSE against " + std::to_string(result.options.referenceSpp) + " spp";
        plot.logX = plot.logY = true;
        for (size_t k = 0; k < result.options.samplings.size(); ++k) {
            LightSampling sampling = result.options.samplings[k];
            PlotSeries measured{several ? lightSamplingName(sampling) : "stratified", colourOf(k), {}, true, true, false};
            for (const ConvergencePoint& p : result.points)
                if (p.sampling == sampling)
                    measured.points.push_back({againstTime ? p.seconds : p.spp, p.rmse, several ? "" : std::to_string(p.spp) + " spp"});
            plot.series.push_back(measured);
        }
        PlotSeries slope{"N^-1/2", "#999999", {}, true, false, true};
        for (const ConvergencePoint& p : result.points)
            if (p.sampling == first.sampling) {
                double x = againstTime ? p.seconds : p.spp, xFirst = againstTime ? first.seconds : first.spp;
                slope.points.push_back({x, first.rmse * std::sqrt(xFirst / x), ""});
            }
        plot.series.push_back(slope);
        std::string path = svgPath;
        if (!againstTime) path.insert(path.size() - 4, "-spp");
        writeSvg(path, plot);
    }
}

}  // namespace rtlab::bench
