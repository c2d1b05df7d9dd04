// Run time against error (a): the renderer's direct lighting with stratified antialiasing,
// rendered at 1, 2, 4, ... 256 samples per pixel and compared with a high-sample reference
// image. The estimator is the renderer's own shading (framework/render/direct_lighting.h) over
// jittered sub-pixel camera rays (Camera::generateRayThrough); only the sample loop lives here,
// because `rtlab render` shoots one ray per pixel centre.
#pragma once

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
};

// A smaller image and fewer samples for --quick.
ConvergenceOptions quickConvergence(ConvergenceOptions options);

struct ConvergencePoint {
    int spp = 0;
    double seconds = 0.0;  // wall time of the render (accelerator built before)
    double rmse = 0.0;     // over all RGB values, radiance units
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
// (svgPath with "-spp" before the extension), each with the N^-1/2 slope of plain Monte Carlo.
void writeConvergenceSvg(const std::string& svgPath, const ConvergenceResult& result);

}  // namespace rtlab::bench
