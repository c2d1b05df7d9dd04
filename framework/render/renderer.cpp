#include "framework/render/renderer.h"

#include "framework/core/error.h"
#include "framework/render/direct_lighting.h"
#include "framework/render/progress_bar.h"
#include "framework/render/tiles.h"

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

}  // namespace

RenderResult Renderer::render(const RenderSettings& settings) const {
    if (settings.width < 1 || settings.height < 1 || settings.width > kMaxImageSide ||
        settings.height > kMaxImageSide)
        throw Error("image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                    " is out of range (1.." + std::to_string(kMaxImageSide) + " per side)");

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
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x) {
                size_t pixel = static_cast<size_t>(y) * settings.width + x;
                Ray ray = camera_.generateRay(x, y, settings.width, settings.height);
                TraversalStats rayStats;
                Hit hit = accelerator_.intersect(ray, rayStats);
                stats.primary += rayStats;
                if (!aovs.cost.empty()) aovs.cost[pixel] = static_cast<uint32_t>(rayStats.steps() + rayStats.primitiveTests);
                if (!aovs.steps.empty()) aovs.steps[pixel] = static_cast<uint32_t>(rayStats.steps());
                if (!aovs.depth.pixels.empty()) aovs.depth.at(x, y, 0) = hit.found() ? hit.t : kInfinity;
                if (!hit.found()) continue;  // misses stay black

                SurfaceHit surface = scene_.surfaceAt(ray, hit);
                result.colour.setRgb(x, y, directLighting(scene_, accelerator_, surface, ray.direction, stats.shadow));
                if (!aovs.primitive.empty()) aovs.primitive[pixel] = hit.prim;
                if (!aovs.normal.pixels.empty())
                    aovs.normal.setRgb(x, y, 0.5f * faceViewer(surface.shadingNormal, ray.direction) + 0.5f);
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
