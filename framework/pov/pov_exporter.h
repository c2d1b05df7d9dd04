// Writes a Scene as a POV-Ray 3.7 scene file that renders the same image as our renderer
// (recipe and measurements: docs/verification.md#1-the-exporter-rtlab-export-pov):
//  - camera: one ray through each pixel centre, `right -x*aspect` for right-handed glTF data,
//    POV-Ray's horizontal `angle` derived from our vertical field of view, `sky` = camera up;
//  - point lights with the fade trick (fade_distance kPovFadeDistance, fade_power 2), so the
//    falloff is I/d^2 to a relative 1e-8/d^2;
//  - Lambert: POV-Ray's diffuse term has no 1/pi, so the light colour carries it:
//    pigment = albedo, light colour = I[W/sr] / pi / (2 FD^2);
//  - emission through `finish { emission }`; meshes as mesh2 (float32 like ours, normals for
//    smooth triangles), analytic spheres as sphere (double, like our oracle).
#pragma once

#include "framework/scene/scene.h"

#include <string>
#include <string_view>

namespace rtlab {

// Recorded in the reference manifest: bump it whenever the exported text changes, so
// `rtlab refs` re-renders every reference.
inline constexpr std::string_view kPovExporterVersion = "rtlab-pov-exporter 1";

// Fade distance of the inverse-square trick: att = 2 / (1 + (d/FD)^2), light colour C/(2 FD^2)
// gives C / (d^2 + FD^2).
inline constexpr double kPovFadeDistance = 1e-4;

// The scene seen through `camera` as a complete .pov file. The camera adapts to whatever +W/+H
// POV-Ray is run with (like ours, it takes the aspect ratio from the image); width and height
// only go into the header comment with the command that renders it.
std::string exportPovScene(const Scene& scene, const Camera& camera, int width, int height);

// Only the geometry, as `#declare <name> = union { triangle {...} ... sphere {...} }` for SDL
// trace(): double-precision triangle objects (mesh2 would round hit points to float32) holding
// our float32 vertices exactly. The scene must have at least one primitive.
std::string exportPovTraceObject(const Scene& scene, std::string_view name);

}  // namespace rtlab
