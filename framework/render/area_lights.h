// The scene's emissive triangles and spheres as the renderer samples them
// (docs/rendering.md#area-and-sphere-lights): converted once into a6's emitters, with the
// probability of picking each proportional to its power (docs/conventions.md#lights-and-units).
#pragma once

#include "framework/interface/radiometry.h"
#include "framework/render/light_sampling.h"
#include "framework/sampling/discrete_distribution.h"
#include "framework/scene/scene.h"

#include <vector>

namespace rtlab {

class AreaLights {
public:
    explicit AreaLights(const Scene& scene);

    bool empty() const { return triangles_.empty() && spheres_.empty(); }
    size_t size() const { return triangles_.size() + spheres_.size(); }

    // One sample of the radiance x reflects from all area lights: with Area or SolidAngle,
    // uPick picks one light by power and u samples it (the estimate divided by the pick's
    // probability); with Hemisphere or Cosine, u is a direction and uPick is not used. Calls
    // the a6 estimators (framework/interface/a6_radiometry.h).
    Vec3 estimate(const ShadingPoint& x, const SceneRays& rays, LightSampling sampling, float uPick, Vec2 u) const;

private:
    std::vector<TriangleEmitter> triangles_;
    std::vector<SphereEmitter> spheres_;
    DiscreteDistribution pick_;  // over triangles_, then spheres_
};

}  // namespace rtlab
