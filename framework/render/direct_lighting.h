// What the renderer computes at a surface point besides the area lights (docs/rendering.md):
// the surface's own emission towards the viewer plus Lambertian reflection (albedo/pi) of every
// point light, falling off as 1/d^2, with hard shadows. No indirect light.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/scene/scene.h"

namespace rtlab {

// A light whose cosine to the viewer-facing normal is below this contributes nothing, as in
// POV-Ray's ComputeOneDiffuseLight; it also keeps grazing and behind-the-surface lights from
// costing a shadow ray.
inline constexpr float kMinLightCosine = 1e-10f;

// The shading normal turned towards the side the ray comes from: surfaces are lit from the
// side they are seen from, whatever their winding (POV-Ray does the same).
inline Vec3 faceViewer(const Vec3& normal, const Vec3& rayDirection) {
    return glm::dot(normal, rayDirection) > 0.0f ? -normal : normal;
}

// Radiance leaving `surface` back along rayDirection: its emission, when its emitting side
// faces the viewer, and the point lights. Shadow queries are counted in shadowStats; none is
// made for a light behind the surface or for a black material.
Vec3 directLighting(const Scene& scene, const Accelerator& accelerator, const SurfaceHit& surface,
                    const Vec3& rayDirection, TraversalStats& shadowStats);

}  // namespace rtlab
