// Run time against error: the renderer (`rtlab render --spp N`: stratified film positions, one
// light sample per camera ray) at 1, 2, 4, ... 256 samples per pixel against a high-sample
// reference image, for one or several ways of sampling the area lights (--light-sampling), with
// each way's efficiency 1 / (MSE x time) relative to the best.
#pragma once

#include "framework/render/light_sampling.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

struct ConvergenceOptions {
    std::string scene = "bunny";
    std::string modelsDir;
    std::string accelerator = "bvh-buckets:12";
    int width = 128;
    int height = 128;
    int referenceSpp = 1024;  // 32 x 32 strata
    std::vector<int> spp{1, 2, 4, 8, 16, 32, 64, 128, 256};
    int threads = 2;
    // One series per way (scenes with only point lights need one); the reference uses the first.
    std::vector<LightSampling> samplings{LightSampling::SolidAngle};
};

// A smaller image and fewer samples for --quick.
ConvergenceOptions quickConvergence(ConvergenceOptions options);
// The estimators of direct light on the penumbra scene (docs/a6-radiometry.md#run-time-against-error).
ConvergenceOptions estimatorComparison(const std::string& scenePath, bool quick);

struct ConvergencePoint {
    LightSampling sampling = LightSampling::SolidAngle;
    int spp = 0;
    double seconds = 0.0;       // wall time of the render (accelerator built before)
    double rmse = 0.0;          // over all RGB values, radiance units
    double relativeRmse = 0.0;  // rmse / mean reference value
};

struct ConvergenceResult {
    ConvergenceOptions options;
    double referenceSeconds = 0.0;
    double referenceMean = 0.0;
    std::vector<ConvergencePoint> points;
    std::string loadAverage;
};

ConvergenceResult runConvergence(const ConvergenceOptions& options);

void writeConvergenceMarkdown(std::ostream& out, const ConvergenceResult& result);
void writeConvergenceCsv(const std::string& path, const ConvergenceResult& result);
// Two log-log plots: error against render time (svgPath) and against samples per pixel
// (svgPath with "-spp" before the extension), one series per sampling, with the N^-1/2 slope
// of plain Monte Carlo through the first series' first point.
void writeConvergenceSvg(const std::string& svgPath, const ConvergenceResult& result);

}  // namespace rtlab::bench
