// POV-Ray as the reference renderer of `rtlab refs` (docs/verification.md): 16-bit linear PNGs
// of the scenes of scenes/, and the parity target our renderer must meet against them.
#include "cli/reference_renderer.h"
#include "framework/accel/accelerator.h"
#include "framework/external/temporary_directory.h"
#include "framework/pov/pov_exporter.h"
#include "framework/pov/pov_reference.h"
#include "framework/pov/povray_process.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/render/renderer.h"

#include <iostream>
#include <memory>

namespace rtlab::cli {
namespace {
namespace fs = std::filesystem;

// The parity target of docs/verification.md: median pixel error 0 codes and at least 99.9 %
// of pixels within 2 codes of POV-Ray.
constexpr double kParityCodes = 2.0;
constexpr double kParityShare = 0.999;

bool povParity(const std::string& name, const Scene& scene, const Camera& camera, const fs::path& reference,
               const fs::path& outputDir, bool keep) {
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator(AcceleratorSpec{});
    accelerator->build(primitives);
    Image referenceImage = readImage(reference.string());
    RenderSettings settings;
    settings.width = referenceImage.width;
    settings.height = referenceImage.height;
    settings.progress = false;
    RenderResult result = Renderer(scene, camera, *accelerator).render(settings);
    fs::path render = outputDir / (name + ".rtlab.png");
    writeImage(render.string(), result.colour);
    ImageComparison c = compareImages(render.string(), reference.string(), kParityCodes);
    double within = 1.0 - c.shareOverThreshold();
    bool meets = c.medianPixelCodes == 0.0 && within >= kParityShare;
    refsLine(name) << (meets ? "meets target: " : "FAIL: ") << "median " << c.medianPixelCodes << " codes, exact "
                   << fixedDigits(100.0 * c.pixelsByCodes[0] / c.pixelCount, 3) << " %, within 2 codes "
                   << fixedDigits(100.0 * within, 3) << " % (" << c.pixelsOverThreshold << " of " << c.pixelCount
                   << " beyond), max " << c.maxCodes() << " codes";
    if (keep) {
        fs::path heat = outputDir / (name + ".heat.png");
        writeErrorHeatMap(render.string(), reference.string(), heat.string());
        std::cout << ", heat map " << heat.string();
    }
    std::cout << "\n";
    return meets;
}

}  // namespace

ReferenceRenderer povReferenceRenderer(const RefsOptions& options) {
    ReferenceRenderer r;
    r.name = "POV-Ray";
    r.manifestFile = "manifest.json";
    r.about = "POV-Ray references made by `rtlab refs` (docs/verification.md); do not edit";
    r.imageExtension = ".png";
    r.exporter = std::string(kPovExporterVersion);
    r.version = povrayVersion();
    r.width = options.width.value_or(320);
    r.height = options.height.value_or(240);
    r.settings = povReferenceSettings(r.width, r.height);
    r.skipReason = [](const Scene&) { return std::string(); };
    r.render = [w = r.width, h = r.height](const Scene& scene, const Camera& camera, const fs::path& image) {
        renderPovReference(scene, camera, w, h, image);
    };
    // Our renders and heat maps go to --parity-dir when given, else to a folder removed after.
    auto scratch = std::make_shared<TemporaryDirectory>("rtlab-refs-parity");
    std::string parityDir = options.parityDir;
    r.parity = [scratch, parityDir](const std::string& name, const Scene& scene, const Camera& camera,
                                    const fs::path& reference) {
        fs::path outputDir = parityDir.empty() ? scratch->path() : fs::path(parityDir);
        fs::create_directories(outputDir);
        return povParity(name, scene, camera, reference, outputDir, !parityDir.empty());
    };
    return r;
}

}  // namespace rtlab::cli
