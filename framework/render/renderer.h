// The renderer (docs/rendering.md): one camera ray through each pixel centre, direct lighting
// from point lights with hard shadows at the first hit, black where the ray misses. Tiles are
// rendered on several threads; the image is bit-identical for every thread count.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/render/aov.h"
#include "framework/render/image.h"
#include "framework/scene/scene.h"

#include <vector>

namespace rtlab {

struct RenderSettings {
    int width = 640;
    int height = 480;
    int threads = 0;        // 0 = one per hardware thread
    std::vector<Aov> aovs;  // the AOV buffers to fill
    bool progress = true;   // draw a progress bar when stderr is a terminal
};

struct RenderResult {
    Image colour;            // linear RGB radiance
    AovBuffers aovs;         // only the requested buffers are filled
    TraversalStats primary;  // camera rays
    TraversalStats shadow;   // shadow rays
    double seconds = 0.0;    // wall time of rendering (the accelerator was built before)
};

class Renderer {
public:
    // The accelerator must have been built over a PrimitiveSet of this scene.
    Renderer(const Scene& scene, const Camera& camera, const Accelerator& accelerator)
        : scene_(scene), camera_(camera), accelerator_(accelerator) {}

    // Throws rtlab::Error for an image size out of range, and whatever the accelerator throws
    // (rtlab::NotImplemented from a stub).
    RenderResult render(const RenderSettings& settings) const;

private:
    const Scene& scene_;
    const Camera& camera_;
    const Accelerator& accelerator_;
};

}  // namespace rtlab
