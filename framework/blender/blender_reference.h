// A Blender Cycles reference render: the scene exported as a Blender script
// (blender_exporter.h), rendered headless in a temporary folder, the 32-bit EXR copied out.
#pragma once

#include "framework/blender/blender_exporter.h"
#include "framework/blender/blender_process.h"

#include <filesystem>

namespace rtlab {

// Exports, renders and writes the EXR to outputExr; returns Blender's wall time in seconds.
// On failure throws rtlab::Error with one line and keeps the folder with the script and log.
double renderBlenderReference(const Scene& scene, const Camera& camera, const BlenderSettings& settings,
                              const std::filesystem::path& outputExr,
                              double timeLimitSeconds = kBlenderTimeLimitSeconds);

}  // namespace rtlab
