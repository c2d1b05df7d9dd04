#include "framework/render/direct_lighting.h"

#include "framework/render/spawn_ray.h"
#include "framework/scene/emitters.h"

#include <cmath>
#include <numbers>

namespace rtlab {

Vec3 directLighting(const Scene& scene, const Accelerator& accelerator, const SurfaceHit& surface,
                    const Vec3& rayDirection, TraversalStats& shadowStats) {
    const Material& material = scene.materials[surface.material];
    Vec3 radiance = material.emission == Vec3(0.0f)
                        ? Vec3(0.0f)
                        : emittedRadiance(scene, surface.prim, surface.geometricNormal, -rayDirection);
    if (material.albedo == Vec3(0.0f)) return radiance;

    Vec3 brdf = material.albedo * std::numbers::inv_pi_v<float>;
    Vec3 normal = faceViewer(surface.shadingNormal, rayDirection);
    for (const PointLight& light : scene.lights) {
        Vec3 toLight = light.position - surface.point;
        float distanceSquared = glm::dot(toLight, toLight);
        float cosine = glm::dot(normal, toLight) / std::sqrt(distanceSquared);
        if (!(cosine >= kMinLightCosine)) continue;  // behind, grazing, or the light on the point
        Ray shadowRay = spawnShadowRay(surface.point, surface.pointError, surface.geometricNormal,
                                       light.position);
        if (accelerator.occluded(shadowRay, shadowStats)) continue;
        radiance += brdf * light.intensity * (cosine / distanceSquared);
    }
    return radiance;
}

}  // namespace rtlab
