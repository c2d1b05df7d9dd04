// The renderer (docs/rendering.md): at one sample per pixel, one camera ray through each pixel
// centre; at N, N stratified camera rays per pixel. At the first hit: the surface's emission,
// point lights with hard shadows, and one sample of the area and sphere lights (soft shadows);
// black where the ray misses. Tiles are rendered on several threads; every pixel draws its
// samples from its own random stream, so the image is bit-identical for every thread count.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/render/aov.h"
#include "framework/render/image.h"
#include "framework/render/light_sampling.h"
#include "framework/scene/scene.h"
#include "framework/scene/triangle_surfaces.h"

#include <vector>

namespace rtlab {

struct RenderSettings {
    int width = 640;
    int height = 480;
    int threads = 0;        // 0 = one per hardware thread
    std::vector<Aov> aovs;  // the AOV buffers to fill (from each pixel's first sample)
    bool progress = true;   // draw a progress bar when stderr is a terminal
    int samplesPerPixel = 1;  // 1 = the pixel centre, as POV-Ray; N = N stratified film positions
    uint64_t seed = 0;        // the random streams of the pixels (docs/conventions.md#sampling)
    LightSampling lightSampling = LightSampling::SolidAngle;  // for emissive triangles and spheres
    // One ray per pixel centre with point lights only and no AOVs: do not trace the camera rays
    // of a tile's row that cannot reach the scene's bounds (BoundsCull). The image is the same
    // with any correct accelerator. Off by default, so that a student's structure is asked
    // every ray and its render shows every answer; the fast paths turn it on.
    bool cullOutsideBounds = false;
};

inline constexpr int kMaxSamplesPerPixel = 1 << 16;

struct RenderResult {
    Image colour;            // linear RGB radiance
    AovBuffers aovs;         // only the requested buffers are filled
    TraversalStats primary;  // camera rays
    TraversalStats shadow;   // shadow rays, and rays that look for emitters
    // Camera rays not traced: their tile row cannot reach the scene's bounds
    // (RenderSettings::cullOutsideBounds). primary.rays counts the others.
    uint64_t culledRays = 0;
    double seconds = 0.0;    // wall time of rendering (the accelerator was built before)
};

class Renderer {
public:
    // The accelerator must have been built over a PrimitiveSet of this scene. Gathers the
    // triangles' shading records (TriangleSurfaces) once, for every render it makes, as the
    // accelerator is built once before them.
    // Asks the accelerator for its queries at the camera's position and at each point light
    // (Accelerator::queriesAt), once, as it gathers the records.
    Renderer(const Scene& scene, const Camera& camera, const Accelerator& accelerator);

    // Throws rtlab::Error for an image size or sample count out of range, and whatever the
    // accelerator or an a6 estimator throws (rtlab::NotImplemented from a stub).
    RenderResult render(const RenderSettings& settings) const;

private:
    const Scene& scene_;
    const Camera& camera_;
    const Accelerator& accelerator_;
    const TriangleSurfaces surfaces_;
    const std::vector<Bounds3f> cullBoxes_;  // sceneBoxes, for BoundsCull
    std::unique_ptr<PointQueries> cameraQueries_;              // null: none
    std::vector<std::unique_ptr<PointQueries>> lightQueries_;  // per point light; null: none
};

}  // namespace rtlab
