// rtlab compare A B [--diff heat.png] [--threshold CODES] [--max-mean CODES] [--max-max CODES]
// [--max-share FRACTION]: two images through OpenImageIO (framework/verification/image_compare.h).
// Errors are printed in image units and in 16-bit codes; the exit status is 1 when a
// tolerance given on the command line is exceeded.
// rtlab compare --blender REF.exr --scene SCENE [--replicates K] [--seed S] [--light-sampling M]:
// our renders of SCENE against a Blender Cycles reference, statistically
// (framework/verification/statistical_comparison.h); exit status 1 when they do not agree.
#include "cli/commands.h"
#include "cli/reference_renderer.h"
#include "cli/statistical_report.h"
#include "framework/core/error.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace rtlab::cli {
namespace {

struct CompareOptions {
    std::string imageA;
    std::string imageB;
    std::string heatMapPath;
    double thresholdCodes = 2.0;
    std::optional<double> maxMeanCodes;
    std::optional<double> maxMaxCodes;
    std::optional<double> maxShare;
    bool blender = false;
    std::string scenePath;
    std::string cameraName;
    int replicates = 256;
    uint64_t seed = 0;
    std::string lightSampling = lightSamplingName(LightSampling::SolidAngle);
};

std::string percent(uint64_t count, uint64_t total) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(3) << (total ? 100.0 * count / total : 0.0) << " %";
    return out.str();
}

// Codes as whole numbers when both images are 16-bit, else with 4 significant digits.
std::string codes(double value, bool whole) {
    std::ostringstream out;
    if (whole)
        out << std::fixed << std::setprecision(0);
    else
        out << std::setprecision(4);
    out << value << " codes";
    return out.str();
}

void printComparison(const CompareOptions& options, const ImageComparison& c) {
    std::ostream& out = std::cout;
    out << "compare " << options.imageA << " vs " << options.imageB << ": " << c.width << "x" << c.height
        << ", " << c.channels << " channels\n";
    out << std::setprecision(4);
    out << "  mean abs error  " << c.meanError << "  (" << codes(c.meanCodes(), false) << ")\n";
    out << "  max abs error   " << c.maxError << "  (" << codes(c.maxCodes(), c.wholeCodes) << ") at pixel (" << c.maxX << ", "
        << c.maxY << ")\n";
    out << "  RMSE            " << c.rmse << "\n";
    out << "  PSNR            " << c.psnr << " dB\n";
    out << "  median pixel    " << codes(c.medianPixelCodes, c.wholeCodes) << "\n";
    const auto& n = c.pixelsByCodes;
    out << "  pixels by error 0: " << n[0] << " (" << percent(n[0], c.pixelCount) << "), 1: " << n[1] << ", 2: "
        << n[2] << ", >2: " << n[3] << "  (codes; " << percent(n[0] + n[1] + n[2], c.pixelCount)
        << " within 2)\n";
    out << "  over threshold  " << c.pixelsOverThreshold << " of " << c.pixelCount << " pixels ("
        << percent(c.pixelsOverThreshold, c.pixelCount) << ") above " << c.thresholdCodes << " codes\n";
}

void compareWithBlender(const CompareOptions& options) {
    Scene scene = loadGltf(options.scenePath);
    const Camera& camera = scene.camera(options.cameraName);
    LightSampling sampling = parseLightSampling(options.lightSampling);
    Image reference = readImage(options.imageA);
    std::cout << "compare " << options.imageA << " (Blender) vs " << options.replicates << " renders of "
              << options.scenePath << " (one sample per pixel, seeds " << options.seed << ".."
              << options.seed + options.replicates - 1 << ", light sampling " << lightSamplingName(sampling) << "): "
              << reference.width << "x" << reference.height << "\n";
    StatisticalComparison c =
        compareWithReferenceImage(scene, camera, reference, options.replicates, options.seed, sampling);
    printRegionTable(std::cout, c);
    std::cout << "  " << (c.passes() ? "agree: " : "DIFFER: ") << statisticalSummary(c) << "\n";
    if (!c.passes())
        throw Error("compare: " + options.scenePath + " does not agree with " + options.imageA + " (" +
                    std::to_string(c.regionFailures()) + " regions, " + std::to_string(c.pixelFailures) +
                    " pixel channels differ)");
}

void compare(const CompareOptions& options) {
    if (options.blender) {
        compareWithBlender(options);
        return;
    }
    ImageComparison comparison = compareImages(options.imageA, options.imageB, options.thresholdCodes);
    printComparison(options, comparison);
    if (!options.heatMapPath.empty()) {
        writeErrorHeatMap(options.imageA, options.imageB, options.heatMapPath);
        std::cout << "  heat map        " << options.heatMapPath << " (" << errorHeatMapLegend() << ")\n";
    }
    std::vector<std::string> exceeded;
    auto check = [&exceeded](const std::optional<double>& limit, double value, const std::string& what) {
        if (limit && !(value <= *limit)) {
            std::ostringstream text;
            text << what << " " << value << " > " << *limit;
            exceeded.push_back(text.str());
        }
    };
    check(options.maxMeanCodes, comparison.meanCodes(), "mean error (codes)");
    check(options.maxMaxCodes, comparison.maxCodes(), "max error (codes)");
    check(options.maxShare, comparison.shareOverThreshold(), "share of pixels over the threshold");
    if (exceeded.empty()) return;
    std::string message = "compare: tolerance exceeded: ";
    for (size_t i = 0; i < exceeded.size(); ++i) message += (i ? "; " : "") + exceeded[i];
    throw Error(message);
}

}  // namespace

void addCompareCommand(CLI::App& app) {
    auto options = std::make_shared<CompareOptions>();
    CLI::App* command = app.add_subcommand(
        "compare", "Compare two images (any format OpenImageIO reads): errors, PSNR, heat map (docs/verification.md)");
    command->add_option("a", options->imageA, "First image (e.g. the render; with --blender the Blender reference)")
        ->required()
        ->check(CLI::ExistingFile);
    auto* b = command->add_option("b", options->imageB, "Second image (e.g. the POV-Ray reference)")
                  ->check(CLI::ExistingFile);
    command->add_option("--diff", options->heatMapPath, "Write an 8-bit PNG heat map of the per-pixel error");
    command->add_option("--threshold", options->thresholdCodes,
                        "A pixel is 'over' when a channel differs by more than this many 16-bit codes")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    command->add_option("--max-mean", options->maxMeanCodes, "Fail when the mean error exceeds this (16-bit codes)")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--max-max", options->maxMaxCodes, "Fail when the max error exceeds this (16-bit codes)")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--max-share", options->maxShare,
                        "Fail when the share of pixels over the threshold exceeds this fraction (0.001 = 0.1 %)")
        ->check(CLI::Range(0.0, 1.0));
    auto* blender = command->add_flag(
        "--blender", options->blender,
        "A is a Blender Cycles reference (EXR): render --scene --replicates times and compare statistically "
        "(docs/verification.md#statistical-comparison)");
    blender->excludes(b);
    command->add_option("--scene", options->scenePath, "With --blender: the scene the reference shows")
        ->needs(blender)
        ->check(CLI::ExistingFile);
    command->add_option("--camera", options->cameraName, "With --blender: camera by name (default: the first)")
        ->needs(blender);
    command->add_option("--replicates", options->replicates, "With --blender: our renders, one sample per pixel each")
        ->capture_default_str()
        ->check(CLI::Range(2, 1 << 20))
        ->needs(blender);
    command->add_option("--seed", options->seed, "With --blender: the first replicate's seed (then +1, +2, ...)")
        ->capture_default_str()
        ->needs(blender);
    command->add_option("--light-sampling", options->lightSampling,
                        "With --blender: area | solid-angle | hemisphere | cosine")
        ->capture_default_str()
        ->needs(blender);
    command->callback([options] {
        if (options->blender && options->scenePath.empty())
            throw CLI::ValidationError("--blender", "needs --scene SCENE, the scene the reference shows");
        if (!options->blender && options->imageB.empty())
            throw CLI::ValidationError("b", "two images are needed (or --blender REF.exr --scene SCENE)");
        compare(*options);
    });
}

}  // namespace rtlab::cli
