#include "framework/scene/emitters.h"

#include <numbers>

namespace rtlab {

std::vector<Emitter> findEmitters(const Scene& scene) {
    std::vector<Emitter> emitters;
    for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim) {
        const Material& material = scene.materials[scene.materialOf(prim)];
        if (material.emission == Vec3(0.0f)) continue;
        Emitter e;
        e.prim = prim;
        e.radiance = material.emission;
        if (scene.isSphere(prim)) {
            double r = scene.sphere(prim).radius;
            e.area = 4.0 * std::numbers::pi * r * r;
        } else {
            auto v = scene.triangleVertices(prim);
            e.area = 0.5 * glm::length(glm::cross(DVec3(v[1]) - DVec3(v[0]), DVec3(v[2]) - DVec3(v[0])));
            e.twoSided = material.doubleSided;
        }
        if (!(e.area > 0.0)) continue;
        // A Lambertian emitter sends pi L per unit area into the hemisphere of each emitting face.
        double meanRadiance = (double(e.radiance.x) + e.radiance.y + e.radiance.z) / 3.0;
        e.power = std::numbers::pi * meanRadiance * e.area * (e.twoSided ? 2.0 : 1.0);
        emitters.push_back(e);
    }
    return emitters;
}

Vec3 emittedRadiance(const Scene& scene, uint32_t prim, const Vec3& normal, const Vec3& towards) {
    const Material& material = scene.materials[scene.materialOf(prim)];
    bool front = glm::dot(normal, towards) > 0.0f;
    bool emits = front || (!scene.isSphere(prim) && material.doubleSided);
    return emits ? material.emission : Vec3(0.0f);
}

}  // namespace rtlab
