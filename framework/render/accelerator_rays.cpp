#include "framework/render/accelerator_rays.h"

#include "framework/render/spawn_ray.h"
#include "framework/scene/emitters.h"

#include <algorithm>
#include <limits>

namespace rtlab {

bool AcceleratorRays::visible(const Vec3& target) const {
    Ray ray = spawnShadowRay(surface_.point, surface_.pointError, surface_.geometricNormal, target);
    return !accelerator_.occluded(ray, stats_);
}

Vec3 AcceleratorRays::incomingEmission(const Vec3& direction) const {
    // A segment as long as the scene, so that the near trim is a fraction of a known length,
    // as for shadow rays: the float triangle test may re-hit the surface the ray leaves.
    Ray ray;
    ray.origin = offsetRayOrigin(surface_.point, surface_.pointError, surface_.geometricNormal, direction);
    ray.direction = direction * reach_;
    ray.tMin = kShadowEpsilon;
    Hit hit = accelerator_.intersect(ray, stats_);
    if (!hit.found()) return Vec3(0.0f);
    SurfaceHit emitter = scene_.surfaceAt(ray, hit);
    return emittedRadiance(scene_, hit.prim, emitter.geometricNormal, -direction);
}

float sceneReach(const Scene& scene) {
    Bounds3f bounds = scene.bounds();
    float diagonal = bounds.isEmpty() ? 0.0f : glm::length(bounds.diagonal());
    return std::max(diagonal, std::numeric_limits<float>::min());
}

}  // namespace rtlab
