// A POV-Ray reference render: the exported scene rendered headless with one ray per pixel
// centre (-A), no display (-D), 16-bit PNG (+FN16) with linear values (File_Gamma=1.0), so
// code = floor(clip(v, 0, 1) * 65535 + 0.5), the same encoding as our 16-bit linear PNG, on
// one thread (+WT1) so that the image is reproducible.
#pragma once

#include "framework/scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtlab {

// Everything on povray's command line that shapes the image, "+W.. +H.. -A -D +FN16
// File_Gamma=1.0 +WT1" (recorded in the reference manifest).
std::string povReferenceSettings(int width, int height);

// Exports the scene, renders it with povray in a temporary folder and writes the PNG to
// outputPng. On failure throws rtlab::Error with one line and keeps the folder with the log.
void renderPovReference(const Scene& scene, const Camera& camera, int width, int height,
                        const std::filesystem::path& outputPng);

// Renders the reference as renderPovReference does, without keeping the image, and returns the
// Trace Time POV-Ray reports in seconds: the rendering alone, without parsing and bounding,
// so it compares with a renderer's time for the same image (bench/render_race.h).
double timePovReference(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace rtlab
