#include "bench/render_race.h"

#include "bench/bench_scenes.h"
#include "bench/report.h"
#include "bench/timing.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/core/error.h"
#include "framework/pov/pov_reference.h"
#include "framework/pov/povray_process.h"
#include "framework/scene/benchmark_rays.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace rtlab::bench {
namespace {

constexpr double kSpeedupTarget = 8.0;
constexpr double kBeyondTracingTarget = 0.15;

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace

RenderRaceOptions quickRenderRace(RenderRaceOptions options) {
    options.size = 196;
    options.repeats = 1;
    return options;
}

RenderRaceResult runRenderRace(const RenderRaceOptions& options) {
    if (options.size < 1 || options.repeats < 1) throw Error("render race: the image size and repeats must be positive");
    Scene scene = loadBenchScene(options.scene, options.modelsDir);
    Camera camera = scene.cameras.empty() ? BenchmarkView(scene.bounds()).camera() : scene.cameras.front();

    RenderRaceResult result;
    result.options = options;
    result.loadAverage = loadAverage();
    result.accelerator = defaultRenderAccelerator();
    AcceleratorSpec spec;
    spec.name = result.accelerator;
    PrimitiveSet primitives(scene);
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
    accelerator->build(primitives);

    std::cerr << "bench: render race on " << options.scene << " at " << options.size << "x" << options.size << std::flush;
    RenderSettings settings;
    settings.width = settings.height = options.size;
    settings.threads = 1;  // POV-Ray's references render on one thread (+WT1)
    settings.cullOutsideBounds = true;  // as rtlab-solution render does with fast/'s structures
    result.share = measureTraceShare(scene, camera, *accelerator, settings, options.repeats);

    // The same image from the textbook BVH (AcceleratorSpec's default), compared bit for bit.
    AcceleratorSpec textbookSpec;
    result.textbookAccelerator = textbookSpec.name;
    std::unique_ptr<Accelerator> textbook = makeAccelerator(textbookSpec);
    textbook->build(primitives);
    settings.progress = false;
    Image fast = Renderer(scene, camera, *accelerator).render(settings).colour;
    RenderSettings textbookSettings = settings;
    textbookSettings.cullOutsideBounds = false;  // every ray asked of the textbook BVH, culled or not
    Image reference = Renderer(scene, camera, *textbook).render(textbookSettings).colour;
    for (size_t i = 0; i < fast.pixels.size(); i += fast.channels)
        result.differentPixels += std::memcmp(&fast.pixels[i], &reference.pixels[i], fast.channels * sizeof(float)) != 0;
    result.povrayVersion = povrayVersion();
    // POV-Ray and our render take turns, so that a slow stretch of this shared machine slows
    // both sides of a pair; the verdict is on the median of the pairs' ratios.
    result.povTraceSeconds = kInfinity;
    Renderer renderer(scene, camera, *accelerator);
    for (int run = 0; run < options.repeats; ++run) {
        double pov = timePovReference(scene, camera, options.size, options.size);
        double ours = renderer.render(settings).seconds;
        result.povTraceSeconds = std::min(result.povTraceSeconds, pov);
        result.pairSpeedups.push_back(pov / ours);
    }
    std::cerr << "\n";
    return result;
}

double RenderRaceResult::pairedSpeedup() const {
    std::vector<double> sorted = pairSpeedups;
    std::sort(sorted.begin(), sorted.end());
    size_t n = sorted.size();
    return n == 0 ? 0.0 : n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

void writeRenderRaceMarkdown(std::ostream& out, const RenderRaceResult& result) {
    const RenderRaceOptions& o = result.options;
    auto [low, high] = result.pairSpeedups.empty() ? std::pair{0.0, 0.0}
                                                   : std::pair{*std::min_element(result.pairSpeedups.begin(), result.pairSpeedups.end()),
                                                               *std::max_element(result.pairSpeedups.begin(), result.pairSpeedups.end())};
    out << "Scene " << o.scene << " at " << o.size << "x" << o.size << ", one ray per pixel centre, one thread, best of "
        << o.repeats << "; load average " << result.loadAverage << ".\n\n"
        << "| renderer | seconds |\n|---|--:|\n"
        << "| rtlab-solution render (" << result.accelerator << ", built before) | " << format("%.3f", result.share.renderSeconds)
        << " |\n"
        << "| its " << result.share.queries << " accelerator queries alone | " << format("%.3f", result.share.traceSeconds)
        << " |\n"
        << "| " << result.povrayVersion << " Trace Time (+WT1) | " << format("%.3f", result.povTraceSeconds) << " |\n\n"
        << "| target | measured | |\n|---|--:|:-:|\n"
        << "| POV-Ray's time / ours ≥ " << format("%.0f", kSpeedupTarget) << " (the median of " << result.pairSpeedups.size()
        << " alternating pairs; min–max " << format("%.2f", low) << "–" << format("%.2f", high) << ") | "
        << format("%.2f", result.pairedSpeedup()) << " | " << verdict(result.pairedSpeedup() >= kSpeedupTarget) << " |\n"
        << "| the same from the best render and the best POV-Ray run | " << format("%.2f", result.speedup()) << " | |\n"
        << "| time beyond tracing ≤ " << format("%.0f", 100 * kBeyondTracingTarget) << " % (the median of the passes' own shares) | "
        << format("%.1f", 100 * result.share.pairedBeyondTracing()) << " % | "
        << verdict(result.share.pairedBeyondTracing() <= kBeyondTracingTarget) << " |\n"
        << "| the same from the best render and the best replay | " << format("%.1f", 100 * result.share.beyondTracing())
        << " % | |\n"
        << "| the image of " << result.textbookAccelerator << " to the bit (pixels that differ) | "
        << result.differentPixels << " | " << verdict(result.differentPixels == 0) << " |\n";
}

}  // namespace rtlab::bench
