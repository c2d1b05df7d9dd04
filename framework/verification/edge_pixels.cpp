#include "framework/verification/edge_pixels.h"

#include "framework/render/direct_lighting.h"
#include "framework/render/spawn_ray.h"

#include <cmath>

namespace rtlab {
namespace {

// What a camera ray through one film position meets: the primitive, and which point lights
// reach it (as directLighting decides: in front of the viewer-facing normal, unshadowed).
std::vector<uint32_t> signature(const Scene& scene, const Accelerator& accelerator, const Ray& ray) {
    TraversalStats stats;
    Hit hit = accelerator.intersect(ray, stats);
    std::vector<uint32_t> seen{hit.prim};
    if (!hit.found()) return seen;
    SurfaceHit surface = scene.surfaceAt(ray, hit);
    Vec3 normal = faceViewer(surface.shadingNormal, ray.direction);
    for (const PointLight& light : scene.lights) {
        Vec3 toLight = light.position - surface.point;
        bool facing = glm::dot(normal, toLight) / std::sqrt(glm::dot(toLight, toLight)) >= kMinLightCosine;
        bool reaches = facing && !accelerator.occluded(
                                     spawnShadowRay(surface.point, surface.pointError, surface.geometricNormal, light.position),
                                     stats);
        seen.push_back(reaches ? 1u : 0u);
    }
    return seen;
}

}  // namespace

std::vector<uint8_t> findEdgePixels(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                                    int width, int height) {
    std::vector<uint8_t> edge(static_cast<size_t>(width) * height, 0);
    constexpr double kOffsets[8][2] = {{0, 0}, {0.5, 0}, {1, 0}, {0, 0.5}, {1, 0.5}, {0, 1}, {0.5, 1}, {1, 1}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::vector<uint32_t> centre = signature(scene, accelerator, camera.generateRay(x, y, width, height));
            for (const auto& offset : kOffsets) {
                Ray ray = camera.generateRayThrough(x + offset[0], y + offset[1], width, height);
                if (signature(scene, accelerator, ray) != centre) {
                    edge[static_cast<size_t>(y) * width + x] = 1;
                    break;
                }
            }
        }
    return edge;
}

}  // namespace rtlab
