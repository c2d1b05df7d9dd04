#include "framework/render/area_lights.h"

#include "framework/interface/a6_radiometry.h"
#include "framework/scene/emitters.h"

namespace rtlab {

AreaLights::AreaLights(const Scene& scene) {
    std::vector<double> trianglePowers, spherePowers;
    for (const Emitter& e : findEmitters(scene)) {
        if (scene.isSphere(e.prim)) {
            const Sphere& s = scene.sphere(e.prim);
            spheres_.push_back({s.centre, s.radius, e.radiance});
            spherePowers.push_back(e.power);
        } else {
            auto v = scene.triangleVertices(e.prim);
            triangles_.push_back({v[0], v[1], v[2], e.radiance, e.twoSided});
            trianglePowers.push_back(e.power);
        }
    }
    trianglePowers.insert(trianglePowers.end(), spherePowers.begin(), spherePowers.end());
    pick_ = DiscreteDistribution(trianglePowers);
}

Vec3 AreaLights::estimate(const ShadingPoint& x, const SceneRays& rays, LightSampling sampling, float uPick, Vec2 u) const {
    if (sampling == LightSampling::Hemisphere) return estimateByUniformHemisphere(x, u, rays);
    if (sampling == LightSampling::Cosine) return estimateByCosineHemisphere(x, u, rays);
    float probability = 0.0f;
    size_t i = pick_.sample(uPick, &probability);
    bool byArea = sampling == LightSampling::Area;
    Vec3 value;
    if (i < triangles_.size())
        value = byArea ? estimateTriangleLightByArea(x, triangles_[i], u, rays) : estimateTriangleLightBySolidAngle(x, triangles_[i], u, rays);
    else
        value = byArea ? estimateSphereLightByArea(x, spheres_[i - triangles_.size()], u, rays)
                       : estimateSphereLightBySolidAngle(x, spheres_[i - triangles_.size()], u, rays);
    return value / probability;
}

}  // namespace rtlab
