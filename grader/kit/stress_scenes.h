// The degenerate scenes of the numerical stress catalogue (docs/conventions.md#stress-catalogue)
// every structure must build and answer correctly: identical centroids, zero extents, one and
// two primitives, degenerate and NaN/infinite triangles, a tree as deep as the cap, 70000
// identical primitives, coordinates near 2^62. Each comes with rays whose answers are exact.
#pragma once

#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct StressRay {
    Ray ray;
    bool occlusionQuery;       // any-hit with ray.tMax instead of closest hit
    bool hit;                  // exact expectation
    std::vector<uint32_t> prims;  // allowed primitives when hit
    float t;
};

struct StressScene {
    std::string id;
    Scene scene;
    std::vector<StressRay> rays;
};

std::vector<StressScene> stressScenes();

}  // namespace rtlab::grader
