// Writes a Scene as a Python script for Blender 3.4 that builds it natively and renders it with
// Cycles, direct light only, into a 32-bit EXR of the radiance our renderer computes (recipe,
// conventions and measurements: docs/verification.md#6-blender-cycles-references):
//  - camera: perspective, vertical field of view = ours, pixel centres as ours (a 0.01 px
//    pixel filter, so every sample is taken at the pixel centre);
//  - point lights in watts: Blender's point light of power P has intensity P / 4 pi W/sr, so
//    P = 4 pi I, radius 0;
//  - materials: Diffuse BSDF (Lambert, albedo / pi); an emitter adds an Emission shader of
//    strength x colour = L, made one-sided (front face only, as ours) unless doubleSided;
//  - emissive triangles cut until no edge is longer than emitterEdge (emitter_tessellation.h);
//  - analytic spheres as Cycles point-cloud spheres (exact, like ours); an emissive sphere is
//    refused: Blender 3.4's sphere light is a disk facing the shading point, so sphere lights
//    are verified against closed forms instead;
//  - a black world; the exact-comparison settings (light sampling threshold 0, no bounces,
//    no denoising, no adaptive sampling, a fixed seed, no clamping, Standard view).
// Coordinates turn from glTF's +Y up to Blender's +Z up: (x, y, z) -> (x, -z, y), exactly.
#pragma once

#include "framework/scene/scene.h"

#include <string>
#include <string_view>

namespace rtlab {

// Recorded in the reference manifest: bump it whenever the exported script changes, so
// `rtlab refs --blender` re-renders every reference.
inline constexpr std::string_view kBlenderExporterVersion = "rtlab-blender-exporter 1";

struct BlenderSettings {
    int width = 160;
    int height = 120;
    int samples = 512;          // Cycles samples per pixel
    int seed = 0;               // cycles.seed: the same seed gives the same image
    double emitterEdge = 0.5;   // the longest edge an emissive triangle may keep [scene units]
};

// What shapes the image besides width and height, as the manifest records it:
// "samples=512 seed=0 emitter-edge=0.25".
std::string blenderSettingsText(const BlenderSettings& settings);

// Why Blender cannot render the scene as our renderer does, in a few words, or "" when it can:
// an emissive sphere (a sphere light).
std::string blenderUnsupported(const Scene& scene);

// The scene seen through `camera` as a complete script; run it as
// `blender -b --factory-startup --python-exit-code 1 -P SCRIPT -- OUT.exr`. Throws
// rtlab::Error with one line naming the scene for what cannot be exported: an emissive
// sphere, a smooth triangle without normals, a primitive naming a missing material,
// settings out of range, a non-finite number.
std::string exportBlenderScene(const Scene& scene, const Camera& camera, const BlenderSettings& settings);

}  // namespace rtlab
