#include "framework/render/renderer.h"

#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/render/accelerator_rays.h"
#include "framework/render/area_lights.h"
#include "framework/render/bounds_cull.h"
#include "framework/render/direct_lighting.h"
#include "framework/render/point_light_batch.h"
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
    uint64_t culledRays = 0;
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

// Renders the pixels of tiles into one RenderResult. Everything that is the same for every
// pixel (the camera's film, the area lights, the scene's reach) is set up once, here.
class TileRenderer {
public:
    TileRenderer(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                 const TriangleSurfaces& surfaces, std::span<const Bounds3f> cullBoxes,
                 const PointQueries* cameraQueries, std::span<const std::unique_ptr<PointQueries>> lightQueries,
                 const RenderSettings& settings,
                 RenderResult& result)
        : scene_(scene),
          accelerator_(accelerator),
          settings_(settings),
          film_(camera.film(settings.width, settings.height)),
          surfaces_(surfaces),
          cameraQueries_(cameraQueries),
          pointLights_(scene, surfaces_, accelerator, lightQueries),
          areaLights_(scene),
          reach_(sceneReach(scene)),
          anyAov_(!settings.aovs.empty()),
          centresOnly_(settings.samplesPerPixel == 1 && areaLights_.empty() && !anyAov_),
          result_(result) {
        centreColumns_.reserve(settings.width);
        for (int x = 0; x < settings.width; ++x) centreColumns_.push_back(film_.column(x + 0.5));
        if (centresOnly_ && settings.cullOutsideBounds) {
            const BoundsCull cull(film_, cullBoxes);
            cullRows_.reserve(settings.height);
            for (int y = 0; y < settings.height; ++y) cullRows_.push_back(cull.row(y));
        }
    }

    void render(const Tile& tile, TileStats& stats) const {
        if (centresOnly_)
            renderCentres(tile, stats);
        else
            renderSamples(tile, stats);
    }

private:
    // One ray through each pixel centre, point lights only and no AOVs: every POV-Ray reference
    // and the benchmark's renders. A few rows' rays are traced, then their hits shaded together
    // (PointLightBatch); nothing is written for a miss (the image starts black), nor traced for
    // a row that cannot reach the scene (BoundsCull). The colour is what renderSamples computes
    // for the same pixel, bit for bit.
    void renderCentres(const Tile& tile, TileStats& stats) const {
        Ray rays[kTileSize];
        HitBatch hits;
        Vec3 radiance[kHitBatchSize];
        for (int y = tile.y0; y < tile.y1; ++y) {
            if (!cullRows_.empty() && cullRows_[y].misses(tile.x0, tile.x1)) {
                stats.culledRays += tile.x1 - tile.x0;
            } else {
                makeCentreRays(tile, y, rays);
                for (int x = tile.x0; x < tile.x1; ++x) {
                    const Ray& ray = rays[x - tile.x0];
                    Hit hit = cameraQueries_ ? cameraQueries_->intersect(ray, stats.primary) : accelerator_.intersect(ray, stats.primary);
                    if (!hit.found()) continue;
                    surfaces_.prefetch(hit.prim);
                    hits.add(x, y, ray, hit);
                }
            }
            if (!hits.full() && y + 1 < tile.y1) continue;
            pointLights_.shade(hits, radiance, stats.shadow);
            for (int k = 0; k < hits.count; ++k) result_.colour.setRgb(hits.x[k], hits.y[k], radiance[k]);
            hits.count = 0;
        }
    }

    // Any sample count, area lights and AOVs.
    void renderSamples(const Tile& tile, TileStats& stats) const {
        const int spp = settings_.samplesPerPixel;
        PixelSamples samples(spp, !areaLights_.empty());
        // At one sample with point lights only no random number is used: none is drawn.
        const bool random = spp > 1 || !areaLights_.empty();
        Ray centreRays[kTileSize];
        for (int y = tile.y0; y < tile.y1; ++y) {
            if (spp == 1) makeCentreRays(tile, y, centreRays);
            for (int x = tile.x0; x < tile.x1; ++x) {
                size_t pixel = static_cast<size_t>(y) * settings_.width + x;
                if (random) samples.generate(settings_.seed, pixel);
                Vec3 sum(0.0f);
                for (int s = 0; s < spp; ++s) {
                    Ray ray = spp == 1 ? centreRays[x - tile.x0] : film_.through(x + samples.film[s].x, y + samples.film[s].y);
                    sum += radiance(ray, samples, s, x, y, pixel, stats);
                }
                result_.colour.setRgb(x, y, sum / static_cast<float>(spp));
            }
        }
    }

    // The rays through the pixel centres of one row of a tile (POV-Ray's rays), made together.
    void makeCentreRays(const Tile& tile, int y, Ray* rays) const {
        film_.throughRow(centreColumns_.data() + tile.x0, tile.x1 - tile.x0, film_.row(y + 0.5), rays);
    }

    // The radiance along camera ray number s of pixel (x, y); the first sample fills the AOVs.
    Vec3 radiance(const Ray& ray, const PixelSamples& samples, int s, int x, int y, size_t pixel, TileStats& stats) const {
        // The accelerator counts straight into the tile's totals; the ray's own work is their
        // difference, taken only for the AOVs.
        const bool aovs = s == 0 && anyAov_;
        const TraversalStats before = aovs ? stats.primary : TraversalStats{};
        Hit hit = accelerator_.intersect(ray, stats.primary);
        Vec3 radiance(0.0f), normal(0.0f);  // misses are black
        if (hit.found()) {
            SurfaceHit surface = surfaces_.surfaceAt(ray, hit);
            normal = faceViewer(surface.shadingNormal, ray.direction);
            radiance = directLighting(scene_, accelerator_, surface, ray.direction, stats.shadow);
            if (!areaLights_.empty()) {
                ShadingPoint point{surface.point, normal, scene_.materials[surface.material].albedo};
                AcceleratorRays rays(scene_, accelerator_, surface, reach_, stats.shadow);
                radiance += areaLights_.estimate(point, rays, settings_.lightSampling, samples.pick[s], samples.light[s]);
            }
        }
        if (aovs) writeAovs(x, y, pixel, hit, normal, before, stats.primary);
        return radiance;
    }

    void writeAovs(int x, int y, size_t pixel, const Hit& hit, const Vec3& normal, const TraversalStats& before,
                   const TraversalStats& after) const {
        AovBuffers& aovs = result_.aovs;
        uint64_t steps = after.steps() - before.steps();
        uint64_t tests = after.primitiveTests - before.primitiveTests;
        if (!aovs.cost.empty()) aovs.cost[pixel] = static_cast<uint32_t>(steps + tests);
        if (!aovs.steps.empty()) aovs.steps[pixel] = static_cast<uint32_t>(steps);
        if (!aovs.depth.pixels.empty()) aovs.depth.at(x, y, 0) = hit.found() ? hit.t : kInfinity;
        if (!aovs.primitive.empty()) aovs.primitive[pixel] = hit.prim;
        if (!aovs.normal.pixels.empty() && hit.found()) aovs.normal.setRgb(x, y, 0.5f * normal + 0.5f);
    }

    const Scene& scene_;
    const Accelerator& accelerator_;
    const RenderSettings& settings_;
    const CameraFilm film_;
    std::vector<DVec3> centreColumns_;  // film_.column of every pixel centre
    std::vector<BoundsCull::Row> cullRows_;  // every image row's, with cullOutsideBounds
    const TriangleSurfaces& surfaces_;
    const PointQueries* cameraQueries_;  // renderCentres' camera rays, when the accelerator made them
    const PointLightBatch pointLights_;  // renderCentres' common hits
    const AreaLights areaLights_;
    const float reach_;
    const bool anyAov_;
    const bool centresOnly_;  // renderCentres does the whole render
    RenderResult& result_;
};

}  // namespace

Renderer::Renderer(const Scene& scene, const Camera& camera, const Accelerator& accelerator)
    : scene_(scene), camera_(camera), accelerator_(accelerator), surfaces_(scene), cullBoxes_(sceneBoxes(scene)) {
    cameraQueries_ = accelerator.queriesAt(camera.film(1, 1).origin);
    for (const PointLight& light : scene.lights) lightQueries_.push_back(accelerator.queriesAt(light.position));
}

RenderResult Renderer::render(const RenderSettings& settings) const {
    if (settings.width < 1 || settings.height < 1 || settings.width > kMaxImageSide ||
        settings.height > kMaxImageSide)
        throw Error("image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                    " is out of range (1.." + std::to_string(kMaxImageSide) + " per side)");
    const int spp = settings.samplesPerPixel;
    if (spp < 1 || spp > kMaxSamplesPerPixel)
        throw Error(std::to_string(spp) + " samples per pixel is out of range (1.." + std::to_string(kMaxSamplesPerPixel) + ")");

    auto start = std::chrono::steady_clock::now();
    RenderResult result;
    result.colour = Image(settings.width, settings.height, 3);
    result.aovs = allocateAovs(settings);
    const TileRenderer renderer(scene_, camera_, accelerator_, surfaces_, cullBoxes_, cameraQueries_.get(), lightQueries_, settings, result);

    std::vector<Tile> tiles = makeTiles(settings.width, settings.height);
    std::vector<TileStats> tileStats(tiles.size());
    ProgressBar progress("rendering", settings.progress ? tiles.size() : 0);
    parallelFor(tiles.size(), settings.threads, [&](size_t tile) {
        renderer.render(tiles[tile], tileStats[tile]);
        progress.advance();
    });

    for (const TileStats& stats : tileStats) {
        result.primary += stats.primary;
        result.shadow += stats.shadow;
        result.culledRays += stats.culledRays;
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace rtlab
