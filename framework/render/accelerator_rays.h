// The scene queries of a6's estimators (framework/interface/radiometry.h, SceneRays) answered
// by the renderer's accelerator for one surface point: shadow rays are any-hit queries, rays
// that look for emitters closest-hit queries, both counted with the shadow rays.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/interface/radiometry.h"
#include "framework/scene/scene.h"

namespace rtlab {

class AcceleratorRays : public SceneRays {
public:
    // reach: a length no scene point is farther than from any other (the scene's diagonal);
    // rays that look for emitters are segments that long.
    AcceleratorRays(const Scene& scene, const Accelerator& accelerator, const SurfaceHit& surface, float reach,
                    TraversalStats& stats)
        : scene_(scene), accelerator_(accelerator), surface_(surface), reach_(reach), stats_(stats) {}

    bool visible(const Vec3& target) const override;
    Vec3 incomingEmission(const Vec3& direction) const override;

private:
    const Scene& scene_;
    const Accelerator& accelerator_;
    const SurfaceHit& surface_;
    float reach_;
    TraversalStats& stats_;
};

// The reach of AcceleratorRays for a scene: the length of its bounds' diagonal (at least the
// smallest normal float, so a scene of one point still gets rays).
float sceneReach(const Scene& scene);

}  // namespace rtlab
