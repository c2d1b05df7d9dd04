#include "framework/render/point_light_batch.h"

#include "framework/core/float_bits.h"
#include "framework/render/direct_lighting.h"
#include "framework/render/spawn_ray.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace rtlab {

namespace {

// c ? a : b, both computed and one kept by its bits. The compiler runs a loop of these on SIMD
// lanes; with ?: it may move a division or a load into the side that needs it, and a loop with
// a side that may trap runs one lane at a time.
float choose(bool c, float a, float b) {
    const uint32_t mask = 0u - static_cast<uint32_t>(c);
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) | (std::bit_cast<uint32_t>(b) & ~mask));
}

// One float per hit in the lanes, one array per coordinate.
struct Floats3 {
    float x[kHitBatchSize], y[kHitBatchSize], z[kHitBatchSize];

    void set(int k, const Vec3& v) {
        x[k] = v.x;
        y[k] = v.y;
        z[k] = v.z;
    }
};

}  // namespace

struct PointLightBatch::Lanes {
    int count = 0;
    int hit[kHitBatchSize];  // index into HitBatch
    // What gather copies of each hit: the barycentrics, the triangle's record, the vertex normals
    // (the face normal where there are none) and the ray's direction.
    float b1[kHitBatchSize], b2[kHitBatchSize];
    Floats3 corner[3], faceNormal, vertexNormal[3], rayDirection;
    float smooth[kHitBatchSize];  // 1 or 0 (a float like the rest, so that the loops run on SIMD lanes)
    // The surfaces, as triangleSurfaceAt gives them.
    Floats3 point, pointError, geometricNormal;
    Floats3 normal;  // the shading normal, turned towards the viewer
    Floats3 brdf;
    Floats3 radiance;
};

PointLightBatch::PointLightBatch(const Scene& scene, const TriangleSurfaces& surfaces, const Accelerator& accelerator,
                                 std::span<const std::unique_ptr<PointQueries>> lightQueries)
    : scene_(scene), accelerator_(accelerator), lightQueries_(lightQueries), surfaces_(surfaces) {
    for (const Material& material : scene.materials) {
        inLanes_.push_back(material.emission == Vec3(0.0f) && material.albedo != Vec3(0.0f));
        brdf_.push_back(material.albedo * std::numbers::inv_pi_v<float>);
    }
}

void PointLightBatch::shade(const HitBatch& hits, Vec3* radiance, TraversalStats& shadowStats) const {
    Lanes lanes;
    gather(hits, lanes, radiance, shadowStats);
    for (size_t i = 0; i < scene_.lights.size(); ++i)
        addLight(scene_.lights[i], i < lightQueries_.size() ? lightQueries_[i].get() : nullptr, lanes, shadowStats);
    for (int k = 0; k < lanes.count; ++k)
        radiance[lanes.hit[k]] = {lanes.radiance.x[k], lanes.radiance.y[k], lanes.radiance.z[k]};
}

// The surface of every hit the lanes take; directLighting shades the rest. The records are
// copied first, so that their loads do not wait for one another, then triangleSurfaceAt's
// arithmetic and faceViewer run lane by lane.
void PointLightBatch::gather(const HitBatch& hits, Lanes& lanes, Vec3* radiance, TraversalStats& shadowStats) const {
    const std::vector<Vec3>& vertexNormals = surfaces_.vertexNormals();
    for (int i = 0; i < hits.count; ++i) {
        const Hit& hit = hits.hit[i];
        const Ray& ray = hits.ray[i];
        const bool triangle = hit.prim < surfaces_.size();
        if (!triangle || !inLanes_[surfaces_.record(hit.prim).material]) {
            radiance[i] = directLighting(scene_, accelerator_, surfaces_.surfaceAt(ray, hit), ray.direction, shadowStats);
            continue;
        }
        const TriangleSurface& record = surfaces_.record(hit.prim);
        const int k = lanes.count++;
        lanes.hit[k] = i;
        lanes.b1[k] = hit.b1;
        lanes.b2[k] = hit.b2;
        lanes.smooth[k] = record.smooth() ? 1.0f : 0.0f;
        for (int v = 0; v < 3; ++v) {
            lanes.corner[v].set(k, record.corners[v]);
            lanes.vertexNormal[v].set(k, record.smooth() ? vertexNormals[record.normals[v]] : record.faceNormal);
        }
        lanes.faceNormal.set(k, record.faceNormal);
        lanes.rayDirection.set(k, ray.direction);
        lanes.brdf.set(k, brdf_[record.material]);
        lanes.radiance.set(k, Vec3(0.0f));
    }
    const Floats3 &v0 = lanes.corner[0], &v1 = lanes.corner[1], &v2 = lanes.corner[2];
    const Floats3 &n0 = lanes.vertexNormal[0], &n1 = lanes.vertexNormal[1], &n2 = lanes.vertexNormal[2];
    const Floats3& face = lanes.faceNormal;
    const Floats3& d = lanes.rayDirection;
    for (int k = 0; k < lanes.count; ++k) {
        const float b0 = 1.0f - lanes.b1[k] - lanes.b2[k], b1 = lanes.b1[k], b2 = lanes.b2[k];
        lanes.point.x[k] = (b0 * v0.x[k] + b1 * v1.x[k]) + b2 * v2.x[k];
        lanes.point.y[k] = (b0 * v0.y[k] + b1 * v1.y[k]) + b2 * v2.y[k];
        lanes.point.z[k] = (b0 * v0.z[k] + b1 * v1.z[k]) + b2 * v2.z[k];
        constexpr float kError = gamma(7);
        lanes.pointError.x[k] = kError * ((std::abs(b0 * v0.x[k]) + std::abs(b1 * v1.x[k])) + std::abs(b2 * v2.x[k]));
        lanes.pointError.y[k] = kError * ((std::abs(b0 * v0.y[k]) + std::abs(b1 * v1.y[k])) + std::abs(b2 * v2.y[k]));
        lanes.pointError.z[k] = kError * ((std::abs(b0 * v0.z[k]) + std::abs(b1 * v1.z[k])) + std::abs(b2 * v2.z[k]));
        const float fx = face.x[k], fy = face.y[k], fz = face.z[k];
        lanes.geometricNormal.x[k] = fx;
        lanes.geometricNormal.y[k] = fy;
        lanes.geometricNormal.z[k] = fz;
        const float sx = (b0 * n0.x[k] + b1 * n1.x[k]) + b2 * n2.x[k];
        const float sy = (b0 * n0.y[k] + b1 * n1.y[k]) + b2 * n2.y[k];
        const float sz = (b0 * n0.z[k] + b1 * n1.z[k]) + b2 * n2.z[k];
        const float length = std::sqrt((sx * sx + sy * sy) + sz * sz);
        const bool interpolated = (lanes.smooth[k] > 0.0f) & (length > 0.0f);
        const float nx = choose(interpolated, sx / length, fx);
        const float ny = choose(interpolated, sy / length, fy);
        const float nz = choose(interpolated, sz / length, fz);
        const bool facesAway = ((nx * d.x[k] + ny * d.y[k]) + nz * d.z[k]) > 0.0f;
        lanes.normal.x[k] = choose(facesAway, -nx, nx);
        lanes.normal.y[k] = choose(facesAway, -ny, ny);
        lanes.normal.z[k] = choose(facesAway, -nz, nz);
    }
}

// directLighting's loop body for one light, a step at a time over the lanes.
void PointLightBatch::addLight(const PointLight& light, const PointQueries* queries, Lanes& lanes,
                               TraversalStats& shadowStats) const {
    const int n = lanes.count;
    const Floats3& p = lanes.point;
    const Floats3& error = lanes.pointError;
    const Floats3& g = lanes.geometricNormal;
    const Floats3& normal = lanes.normal;
    const Vec3 target = light.position;
    float cosine[kHitBatchSize], distanceSquared[kHitBatchSize];
    Floats3 origin, direction;
    uint32_t lit[kHitBatchSize];  // 1 or 0, as wide as the floats beside it
    // The cosine at the surface, and spawnShadowRay(p, error, g, target).
    for (int k = 0; k < n; ++k) {
        const float tx = target.x - p.x[k], ty = target.y - p.y[k], tz = target.z - p.z[k];
        distanceSquared[k] = (tx * tx + ty * ty) + tz * tz;
        cosine[k] = ((normal.x[k] * tx + normal.y[k] * ty) + normal.z[k] * tz) / std::sqrt(distanceSquared[k]);
        lit[k] = cosine[k] >= kMinLightCosine;
        const float distance = (std::abs(g.x[k]) * error.x[k] + std::abs(g.y[k]) * error.y[k]) + std::abs(g.z[k]) * error.z[k];
        const bool behind = ((tx * g.x[k] + ty * g.y[k]) + tz * g.z[k]) < 0.0f;
        const float ox = choose(behind, -(distance * g.x[k]), distance * g.x[k]);
        const float oy = choose(behind, -(distance * g.y[k]), distance * g.y[k]);
        const float oz = choose(behind, -(distance * g.z[k]), distance * g.z[k]);
        origin.x[k] = floatStep(p.x[k] + ox, ox);
        origin.y[k] = floatStep(p.y[k] + oy, oy);
        origin.z[k] = floatStep(p.z[k] + oz, oz);
        direction.x[k] = target.x - origin.x[k];
        direction.y[k] = target.y - origin.y[k];
        direction.z[k] = target.z - origin.z[k];
    }
    for (int k = 0; k < n; ++k) {
        if (!lit[k]) continue;
        Ray shadowRay;
        shadowRay.origin = {origin.x[k], origin.y[k], origin.z[k]};
        shadowRay.direction = {direction.x[k], direction.y[k], direction.z[k]};
        shadowRay.tMin = kShadowEpsilon;
        shadowRay.tMax = 1.0f - kShadowEpsilon;
        lit[k] = !(queries ? queries->occluded(shadowRay, shadowStats) : accelerator_.occluded(shadowRay, shadowStats));
    }
    // brdf * intensity * (cosine / d^2), added where the light is seen.
    const Vec3 intensity = light.intensity;
    Floats3& radiance = lanes.radiance;
    for (int k = 0; k < n; ++k) {
        const float falloff = cosine[k] / distanceSquared[k];
        radiance.x[k] += choose(lit[k] != 0, lanes.brdf.x[k] * intensity.x * falloff, 0.0f);
        radiance.y[k] += choose(lit[k] != 0, lanes.brdf.y[k] * intensity.y * falloff, 0.0f);
        radiance.z[k] += choose(lit[k] != 0, lanes.brdf.z[k] * intensity.z * falloff, 0.0f);
    }
}

}  // namespace rtlab
