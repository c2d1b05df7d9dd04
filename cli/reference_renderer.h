// The two reference renderers of `rtlab refs` (docs/verification.md): POV-Ray for the scenes of
// scenes/, Blender Cycles (--blender) for the radiometry scenes of scenes/radiometry/. The
// command's bookkeeping is the same for both (which scenes, the manifest of input hashes, what
// changed, --check re-rendering into a scratch folder); what differs is described here.
#pragma once

#include "framework/render/light_sampling.h"
#include "framework/verification/statistical_comparison.h"
#include "framework/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::cli {

struct RefsOptions {
    std::vector<std::string> scenePaths;
    std::string scenesDir = "scenes";
    std::optional<int> width;   // default: the renderer's
    std::optional<int> height;
    bool force = false;
    bool check = false;
    bool hits = false;
    bool parity = false;
    bool blender = false;
    std::string parityDir;
    size_t rays = 3000;
    uint64_t seed = 1;
    std::optional<int> samples;  // Blender: Cycles samples per pixel
    int replicates = 256;        // Blender --parity: our renders, one sample per pixel each
};

struct ReferenceRenderer {
    std::string name;             // "POV-Ray", "Blender"
    std::string scenesSubfolder;  // its scenes: DIR/<this>/*.gltf ("" for DIR itself)
    std::string manifestFile;     // in DIR/refs
    std::string about;            // the manifest's line for its reader
    std::string imageExtension;   // ".png", ".exr"
    std::string exporter;         // the exporter's version
    std::string version;          // the renderer's version line
    int width = 0;
    int height = 0;
    std::string settings;  // everything else that shapes the image
    // How far a re-render (--check) may lie from the committed image: the RMS of their
    // difference over the committed image's mean. 0 demands identical pixels.
    double recheckTolerance = 0.0;
    // Why a scene gets no reference from this renderer (printed; the scene is skipped), or "".
    std::function<std::string(const Scene&)> skipReason;
    std::function<void(const Scene&, const Camera&, const std::filesystem::path& image)> render;
    // Our renderer (the implementation this executable links) against the reference: prints
    // its figures after the scene's name and returns whether the target was met.
    std::function<bool(const std::string& name, const Scene&, const Camera&, const std::filesystem::path& reference)>
        parity;
};

ReferenceRenderer povReferenceRenderer(const RefsOptions& options);
ReferenceRenderer blenderReferenceRenderer(const RefsOptions& options);

// Our renderer's `replicates` renders of the scene (one sample per pixel, seeds firstSeed, ...)
// at the reference image's size, compared statistically with it: the test of the Blender
// references (docs/verification.md#statistical-comparison).
StatisticalComparison compareWithReferenceImage(const Scene& scene, const Camera& camera, const Image& reference,
                                                int replicates, uint64_t firstSeed, LightSampling lightSampling,
                                                Image* ourMean = nullptr);

// "  name             " for a line of the command's report.
std::ostream& refsLine(const std::string& name);
std::string fixedDigits(double value, int digits);

}  // namespace rtlab::cli
