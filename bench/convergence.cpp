#include "bench/convergence.h"

#include "bench/bench_scenes.h"
#include "bench/svg_plot.h"
#include "bench/timing.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/primitive_set.h"
#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/render/direct_lighting.h"
#include "framework/render/image.h"
#include "framework/render/tiles.h"
#include "framework/scene/benchmark_rays.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace rtlab::bench {

namespace {

// Radiance along one camera ray, exactly as the renderer shades a pixel: black on a miss,
// direct lighting with hard shadows at the first hit.
Vec3 radiance(const Scene& scene, const Accelerator& accelerator, const Ray& ray) {
    TraversalStats stats;
    Hit hit = accelerator.intersect(ray, stats);
    if (!hit.found()) return Vec3(0.0f);
    return directLighting(scene, accelerator, scene.surfaceAt(ray, hit), ray.direction, stats);
}

// spp samples per pixel on a jittered a x b grid (a = b for square counts, else a = 2b):
// stratum (sx, sy) gets one uniform point inside it. Each pixel has its own PCG32 stream, so
// the image does not depend on the thread count; `seed` separates the reference's samples.
Image renderStratified(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                       const ConvergenceOptions& options, int spp, uint64_t seed) {
    int columns = 1;
    while (columns * columns < spp) columns *= 2;
    int rows = spp / columns;
    Image image(options.width, options.height, 3);
    parallelFor(static_cast<size_t>(options.height), options.threads, [&](size_t row) {
        int y = static_cast<int>(row);
        for (int x = 0; x < options.width; ++x) {
            Pcg32 rng(seed, static_cast<uint64_t>(y) * options.width + x);
            Vec3 sum(0.0f);
            for (int sy = 0; sy < rows; ++sy)
                for (int sx = 0; sx < columns; ++sx) {
                    double filmX = x + (sx + rng.uniform()) / columns;
                    double filmY = y + (sy + rng.uniform()) / rows;
                    sum += radiance(scene, accelerator, camera.generateRayThrough(filmX, filmY, options.width, options.height));
                }
            image.setRgb(x, y, sum / static_cast<float>(spp));
        }
    });
    return image;
}

double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        double d = static_cast<double>(a.pixels[i]) - b.pixels[i];
        sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(a.pixels.size()));
}

}  // namespace

ConvergenceOptions quickConvergence(ConvergenceOptions options) {
    options.width = options.height = 48;
    options.referenceSpp = 64;
    options.spp = {1, 4, 16};
    return options;
}

ConvergenceResult runConvergence(const ConvergenceOptions& options) {
    for (int spp : options.spp)
        if (spp < 1 || (spp & (spp - 1)) != 0) throw Error("samples per pixel must be powers of two, not " + std::to_string(spp));
    Scene scene = loadBenchScene(options.scene, options.modelsDir);
    if (scene.lights.empty()) throw Error(options.scene + ": the samples-per-pixel study needs a scene with a light");
    Camera camera = scene.cameras.empty() ? BenchmarkView(scene.bounds()).camera() : scene.cameras.front();
    PrimitiveSet primitives(scene);
    AcceleratorSpec spec;
    spec.name = options.accelerator;
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
    accelerator->build(primitives);

    ConvergenceResult result;
    result.options = options;
    result.loadAverage = loadAverage();
    std::cerr << "bench: convergence on " << options.scene << ": reference at " << options.referenceSpp << " spp"
              << std::flush;
    auto start = std::chrono::steady_clock::now();
    Image reference = renderStratified(scene, camera, *accelerator, options, options.referenceSpp, 1);
    result.referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double total = 0.0;
    for (float v : reference.pixels) total += v;
    result.referenceMean = total / static_cast<double>(reference.pixels.size());

    for (int spp : options.spp) {
        std::cerr << ", " << spp << std::flush;
        auto begin = std::chrono::steady_clock::now();
        Image image = renderStratified(scene, camera, *accelerator, options, spp, 2);
        ConvergencePoint point;
        point.spp = spp;
        point.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        point.rmse = rmse(image, reference);
        point.relativeRmse = result.referenceMean > 0.0 ? point.rmse / result.referenceMean : 0.0;
        result.points.push_back(point);
    }
    std::cerr << " spp\n";
    return result;
}

void writeConvergenceMarkdown(std::ostream& out, const ConvergenceResult& result) {
    const ConvergenceOptions& o = result.options;
    out << "\n" << o.scene << ", " << o.width << "x" << o.height << ", rtlab:" << o.accelerator << ", " << o.threads
        << " threads, reference " << o.referenceSpp << " spp (" << result.referenceSeconds << " s); load average "
        << result.loadAverage << "\n\n| spp | render s | RMSE | RMSE / mean |\n|--:|--:|--:|--:|\n";
    for (const ConvergencePoint& p : result.points) {
        char line[128];
        std::snprintf(line, sizeof line, "| %d | %.3f | %.3g | %.3g |\n", p.spp, p.seconds, p.rmse, p.relativeRmse);
        out << line;
    }
    if (result.points.size() >= 2) {
        const ConvergencePoint& a = result.points.front();
        const ConvergencePoint& b = result.points.back();
        out << "\nError slope from " << a.spp << " to " << b.spp << " spp: "
            << std::log(b.rmse / a.rmse) / std::log(static_cast<double>(b.spp) / a.spp)
            << " (plain Monte Carlo: -0.5; stratified samples converge faster at edges and shadow boundaries).\n";
    }
}

void writeConvergenceCsv(const std::string& path, const ConvergenceResult& result) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot open for writing");
    out << "scene,accelerator,width,height,reference_spp,spp,seconds,rmse,relative_rmse\n";
    for (const ConvergencePoint& p : result.points)
        out << result.options.scene << ",rtlab:" << result.options.accelerator << ',' << result.options.width << ','
            << result.options.height << ',' << result.options.referenceSpp << ',' << p.spp << ',' << p.seconds << ','
            << p.rmse << ',' << p.relativeRmse << '\n';
    if (!out.flush()) throw Error(path + ": write failed");
}

void writeConvergenceSvg(const std::string& svgPath, const ConvergenceResult& result) {
    if (result.points.empty()) return;
    const ConvergencePoint& first = result.points.front();
    for (bool againstTime : {true, false}) {
        Plot plot;
        plot.title = "Image error against " + std::string(againstTime ? "render time" : "samples per pixel") + " (" +
                     result.options.scene + ")";
        plot.xLabel = againstTime ? "render time [s]" : "samples per pixel";
        plot.yLabel = "RMSE against " + std::to_string(result.options.referenceSpp) + " spp";
        plot.logX = plot.logY = true;
        PlotSeries measured{"stratified", "#1f77b4", {}, true, true, false};
        PlotSeries slope{"N^-1/2", "#999999", {}, true, false, true};
        for (const ConvergencePoint& p : result.points) {
            double x = againstTime ? p.seconds : p.spp;
            measured.points.push_back({x, p.rmse, std::to_string(p.spp) + " spp"});
            double xFirst = againstTime ? first.seconds : first.spp;
            slope.points.push_back({x, first.rmse * std::sqrt(xFirst / x), ""});
        }
        plot.series = {measured, slope};
        std::string path = svgPath;
        if (!againstTime) path.insert(path.size() - 4, "-spp");
        writeSvg(path, plot);
    }
}

}  // namespace rtlab::bench
