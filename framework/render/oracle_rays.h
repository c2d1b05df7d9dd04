// SceneRays answered exactly by the oracle: what a6's estimators are graded with
// (grader/a6_radiometry/worker/radiometry_tasks.cpp). The grader's shading points float in
// space (no surface under them), so rays start at the point itself and only the shadow-ray trims
// of the renderer apply. Also what the test suite runs the reference estimators with, to check
// the grader's closed forms and spreads against them.
#pragma once

#include "framework/interface/radiometry.h"
#include "framework/oracle/oracle.h"
#include "framework/render/spawn_ray.h"
#include "framework/scene/emitters.h"

#include <limits>

namespace rtlab {

class OracleRays : public SceneRays {
public:
    // `scene` and `oracle` (built over it) must outlive the rays.
    OracleRays(const Scene& scene, const Oracle& oracle, const Vec3& point)
        : scene_(scene), oracle_(oracle), point_(point), reach_(reachAcross(scene, point)) {}

    bool visible(const Vec3& target) const override {
        OracleRay ray{DVec3(point_), DVec3(target) - DVec3(point_), kShadowEpsilon, 1.0 - kShadowEpsilon};
        return !oracle_.anyHit(ray);
    }
    Vec3 incomingEmission(const Vec3& direction) const override {
        OracleRay ray{DVec3(point_), DVec3(direction) * reach_, kShadowEpsilon, std::numeric_limits<double>::infinity()};
        OracleHit hit = oracle_.closestHit(ray);
        return hit.hit ? emittedRadiance(scene_, hit.prim, Vec3(hit.normal), -direction) : Vec3(0.0f);
    }

private:
    // The length the emission ray's direction is scaled to: twice the extent of the scene and
    // the point, beyond every surface.
    static double reachAcross(const Scene& scene, const Vec3& point) {
        Bounds3f bounds = scene.bounds();
        bounds.extend(point);
        return 2.0 * glm::length(bounds.diagonal());
    }

    const Scene& scene_;
    const Oracle& oracle_;
    Vec3 point_;
    double reach_;
};

}  // namespace rtlab
