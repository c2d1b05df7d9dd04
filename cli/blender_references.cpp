// Blender Cycles as the reference renderer of `rtlab refs --blender`
// (docs/verification.md#6-blender-cycles-references): 32-bit EXRs of the radiometry scenes of
// scenes/radiometry/, and the statistical comparison our renderer must pass against them.
#include "cli/reference_renderer.h"
#include "cli/statistical_report.h"
#include "framework/accel/accelerator.h"
#include "framework/blender/blender_reference.h"
#include "framework/verification/edge_pixels.h"
#include "framework/render/image_io.h"
#include "framework/verification/replicates.h"

#include <chrono>
#include <iostream>

namespace rtlab::cli {
namespace fs = std::filesystem;

StatisticalComparison compareWithReferenceImage(const Scene& scene, const Camera& camera, const Image& reference,
                                                int replicates, uint64_t firstSeed, LightSampling lightSampling,
                                                Image* ourMean) {
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator(AcceleratorSpec{});
    accelerator->build(primitives);
    RenderSettings settings;
    settings.width = reference.width;
    settings.height = reference.height;
    settings.progress = false;
    settings.lightSampling = lightSampling;
    ReplicateStatistics ours = renderReplicates(scene, camera, *accelerator, settings, replicates, firstSeed);
    if (ourMean) *ourMean = ours.meanImage();
    return compareStatistically(ours, reference, findEdgePixels(scene, camera, *accelerator, reference.width, reference.height));
}

ReferenceRenderer blenderReferenceRenderer(const RefsOptions& options) {
    BlenderSettings settings;
    settings.width = options.width.value_or(settings.width);
    settings.height = options.height.value_or(settings.height);
    settings.samples = options.samples.value_or(settings.samples);
    ReferenceRenderer r;
    r.name = "Blender";
    r.scenesSubfolder = "radiometry";
    r.manifestFile = "blender-manifest.json";
    r.about = "Blender Cycles references made by `rtlab refs --blender` (docs/verification.md); do not edit";
    r.imageExtension = ".exr";
    r.exporter = std::string(kBlenderExporterVersion);
    r.version = blenderVersion();
    r.width = settings.width;
    r.height = settings.height;
    r.settings = blenderSettingsText(settings);
    // Cycles picks its CPU kernels by the machine: on another CPU the same seed gives pixels
    // that differ by rounding, and a few light samples that take the other branch (measured:
    // RMS 4.2e-5 on mixed-lights, 2e-4 of its mean, 0.9 % of the pixels off by more than 1e-6).
    // Any change of the scene, the exporter or the sampling moves the RMS by percents.
    r.recheckTolerance = 1e-3;
    r.skipReason = blenderUnsupported;
    r.render = [settings](const Scene& scene, const Camera& camera, const fs::path& image) {
        renderBlenderReference(scene, camera, settings, image);
    };
    int replicates = options.replicates;
    std::string parityDir = options.parityDir;
    r.parity = [replicates, parityDir](const std::string& name, const Scene& scene, const Camera& camera,
                                       const fs::path& reference) {
        auto start = std::chrono::steady_clock::now();
        Image ourMean;
        StatisticalComparison c = compareWithReferenceImage(scene, camera, readImage(reference.string()), replicates, 0,
                                                            RenderSettings().lightSampling, &ourMean);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        refsLine(name) << (c.passes() ? "agrees: " : "FAIL: ") << statisticalSummary(c) << ", "
                       << fixedDigits(seconds, 1) << " s";
        if (!parityDir.empty()) {
            fs::create_directories(parityDir);
            fs::path mean = fs::path(parityDir) / (name + ".rtlab.exr");
            writeImage(mean.string(), ourMean);
            std::cout << ", our mean " << mean.string();
        }
        std::cout << "\n";
        return c.passes();
    };
    return r;
}

}  // namespace rtlab::cli
