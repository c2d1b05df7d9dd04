#include "framework/render/renderer.h"

#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/render/accelerator_rays.h"
#include "framework/render/area_lights.h"
#include "framework/render/direct_lighting.h"
#include "framework/render/progress_bar.h"
#include "framework/render/tiles.h"
#include "framework/sampling/stratified.h"

#include <algorithm>
#include <chrono>
#include <string>

namespace rtlab {

static constexpr int kMaxImageSide = 1 << 15;

namespace {

bool wants(const RenderSettings& settings, Aov aov) {
    return std::find(settings.aovs.begin(), settings.aovs.end(), aov) != settings.aovs.end();
}

AovBuffers allocateAovs(const RenderSettings& settings) {
    AovBuffers buffers;
    size_t pixels = static_cast<size_t>(settings.width) * settings.height;
    if (wants(settings, Aov::Normal)) buffers.normal = Image(settings.width, settings.height, 3);
    if (wants(settings, Aov::Depth)) buffers.depth = Image(settings.width, settings.height, 1);
    if (wants(settings, Aov::Primitive)) buffers.primitive.assign(pixels, kNoHit);
    if (wants(settings, Aov::Cost)) buffers.cost.assign(pixels, 0);
    if (wants(settings, Aov::Steps)) buffers.steps.assign(pixels, 0);
    return buffers;
}

// The work counters of one tile, kept apart so the totals are summed in tile order.
struct TileStats {
    TraversalStats primary;
    TraversalStats shadow;
};

// The stratified samples of one pixel (docs/conventions.md#sampling): film positions, then
// light picks and light points when the scene has area lights, all from the pixel's own PCG32
// stream (sequence = pixel index), so a pixel's samples do not depend on who renders it.
struct PixelSamples {
    std::vector<Vec2> film, light;
    std::vector<float> pick;

    PixelSamples(int count, bool areaLights)
        : film(static_cast<size_t>(count)), light(areaLights ? count : 0), pick(areaLights ? count : 0) {}

    void generate(uint64_t seed, uint64_t pixel) {
        Pcg32 rng(seed, pixel);
        stratified2D(rng, film);
        stratified1D(rng, pick);
        stratified2D(rng, light);
    }
};

}  // namespace

RenderResult Renderer::render(const RenderSettings& settings) const {
    if (settings.width < 1 || settings.height < 1 || settings.width > kMaxImageSide ||
        settings.height > kMaxImageSide)
        throw Error("image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                    " is out of range (1.." + std::to_string(kMaxImageSide) + " per side)");
    const int spp = settings.samplesPerPixel;
    if (spp < 1 || spp > kMaxSamplesPerPixel)
        throw Error(std::to_string(spp) + " samples per pixel is out of range (1.." + std::to_string(kMaxSamplesPerPixel) + ")");
    const AreaLights areaLights(scene_);
    const float reach = sceneReach(scene_);

    auto start = std::chrono::steady_clock::now();
    RenderResult result;
    result.colour = Image(settings.width, settings.height, 3);
    result.aovs = allocateAovs(settings);
    AovBuffers& aovs = result.aovs;

    std::vector<Tile> tiles = makeTiles(settings.width, settings.height);
    std::vector<TileStats> tileStats(tiles.size());
    ProgressBar progress("rendering", settings.progress ? tiles.size() : 0);

    parallelFor(tiles.size(), settings.threads, [&](size_t tileIndex) {
        const Tile& tile = tiles[tileIndex];
        TileStats& stats = tileStats[tileIndex];
        PixelSamples samples(spp, !areaLights.empty());
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x) {
                size_t pixel = static_cast<size_t>(y) * settings.width + x;
                samples.generate(settings.seed, pixel);
                Vec3 sum(0.0f);
                for (int s = 0; s < spp; ++s) {
                    // One sample keeps POV-Ray's ray through the pixel centre.
                    Ray ray = spp == 1 ? camera_.generateRay(x, y, settings.width, settings.height)
                                       : camera_.generateRayThrough(x + samples.film[s].x, y + samples.film[s].y,
                                                                    settings.width, settings.height);
                    TraversalStats rayStats;
                    Hit hit = accelerator_.intersect(ray, rayStats);
                    stats.primary += rayStats;
                    if (s == 0) {
                        if (!aovs.cost.empty()) aovs.cost[pixel] = static_cast<uint32_t>(rayStats.steps() + rayStats.primitiveTests);
                        if (!aovs.steps.empty()) aovs.steps[pixel] = static_cast<uint32_t>(rayStats.steps());
                        if (!aovs.depth.pixels.empty()) aovs.depth.at(x, y, 0) = hit.found() ? hit.t : kInfinity;
                    }
                    if (!hit.found()) continue;  // misses are black

                    SurfaceHit surface = scene_.surfaceAt(ray, hit);
                    Vec3 normal = faceViewer(surface.shadingNormal, ray.direction);
                    Vec3 radiance = directLighting(scene_, accelerator_, surface, ray.direction, stats.shadow);
                    if (!areaLights.empty()) {
                        ShadingPoint point{surface.point, normal, scene_.materials[surface.material].albedo};
                        AcceleratorRays rays(scene_, accelerator_, surface, reach, stats.shadow);
                        radiance += areaLights.estimate(point, rays, settings.lightSampling, samples.pick[s], samples.light[s]);
                    }
                    sum += radiance;
                    if (s == 0) {
                        if (!aovs.primitive.empty()) aovs.primitive[pixel] = hit.prim;
                        if (!aovs.normal.pixels.empty()) aovs.normal.setRgb(x, y, 0.5f * normal + 0.5f);
                    }
                }
                result.colour.setRgb(x, y, sum / static_cast<float>(spp));
            }
        }
        progress.advance();
    });

    for (const TileStats& stats : tileStats) {
        result.primary += stats.primary;
        result.shadow += stats.shadow;
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace rtlab
