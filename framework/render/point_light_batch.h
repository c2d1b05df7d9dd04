// The point lights at a batch of hits, shaded together (docs/performance.md#the-renderer).
// Shading one hit at a time, every step waits for the one before it: the triangle's record
// comes from memory only once the traversal has named it, the shadow ray's origin waits for
// the surface, and the next camera ray waits for all of it. Here a few tile rows' camera rays
// are traced first and their hits kept; then the records of all of them are read (their loads
// overlap, and were started as each hit was found), and each later step is a plain loop over
// arrays, one per coordinate, which the compiler runs on SIMD lanes: the surfaces, the cosines
// and shadow rays of every hit, then the shadow queries, then the sums. Each colour is directLighting's for the same hit, bit for bit
// (tests/test_renderer.cpp): the same operations in the same order, lane by lane.
//
// The lanes take the common hits: triangles of a material that reflects light and emits none.
// The others (spheres, emitters, black surfaces) are shaded by directLighting itself.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/render/tiles.h"
#include "framework/scene/triangle_surfaces.h"

#include <memory>
#include <span>
#include <vector>

namespace rtlab {

// Camera rays that hit, from a few rows of a tile, waiting to be shaded together.
inline constexpr int kHitBatchSize = 4 * kTileSize;

struct HitBatch {
    int count = 0;
    int x[kHitBatchSize], y[kHitBatchSize];  // the pixel
    Ray ray[kHitBatchSize];
    Hit hit[kHitBatchSize];

    // Whether the hits of one more tile row might not fit.
    bool full() const { return count > kHitBatchSize - kTileSize; }
    void add(int px, int py, const Ray& r, const Hit& h) {
        x[count] = px;
        y[count] = py;
        ray[count] = r;
        hit[count++] = h;
    }
};

class PointLightBatch {
public:
    // lightQueries[i], when there is one, answers the shadow rays toward scene.lights[i]
    // (Accelerator::queriesAt); the accelerator answers the others.
    PointLightBatch(const Scene& scene, const TriangleSurfaces& surfaces, const Accelerator& accelerator,
                    std::span<const std::unique_ptr<PointQueries>> lightQueries);

    // radiance[k] is the light leaving hit k back along its ray: the point lights' reflection
    // with hard shadows, or directLighting's answer for a hit the lanes do not take. Shadow
    // queries are counted in shadowStats.
    void shade(const HitBatch& hits, Vec3* radiance, TraversalStats& shadowStats) const;

private:
    struct Lanes;
    void gather(const HitBatch& hits, Lanes& lanes, Vec3* radiance, TraversalStats& shadowStats) const;
    void addLight(const PointLight& light, const PointQueries* queries, Lanes& lanes, TraversalStats& shadowStats) const;

    const Scene& scene_;
    const Accelerator& accelerator_;
    std::span<const std::unique_ptr<PointQueries>> lightQueries_;
    const TriangleSurfaces& surfaces_;
    std::vector<uint8_t> inLanes_;  // per material: reflects and does not emit
    std::vector<Vec3> brdf_;        // per material: albedo / pi
};

}  // namespace rtlab
