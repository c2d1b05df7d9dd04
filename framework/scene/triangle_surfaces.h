// What shading reads of a triangle at a hit: its corners, its unit face normal, where its
// vertex normals are and its material, in one 64-byte record. A renderer gathers every
// triangle's record once per image (TriangleSurfaces), so a hit loads one cache line instead of
// an index and then three corners, and takes no cross product, square root and division for
// the face normal on the way to its shadow rays. Scene::surfaceAt gathers the one record it
// needs; both compute the SurfaceHit with triangleSurfaceAt, so they agree bit for bit.
#pragma once

#include "framework/scene/scene.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

// TriangleSurface::normals of a triangle shaded flat.
inline constexpr uint32_t kFlatTriangle = 0xffffffffu;

struct alignas(64) TriangleSurface {
    std::array<Vec3, 3> corners;
    Vec3 faceNormal;                  // unit, from the winding; +z for a degenerate triangle
    std::array<uint32_t, 3> normals;  // into Triangles::normals, or kFlatTriangle in [0]
    uint32_t material = 0;

    bool smooth() const { return normals[0] != kFlatTriangle; }
};

// The record of triangle `prim` of the scene.
TriangleSurface gatherTriangleSurface(const Scene& scene, uint32_t prim);

// The surface at a hit on the triangle: the point rebuilt from the barycentrics with its error
// bound (pbrt-v4 6.8.5), the face normal, and the interpolated vertex normal when it is smooth.
SurfaceHit triangleSurfaceAt(const TriangleSurface& triangle, const std::vector<Vec3>& vertexNormals,
                             const Hit& hit);

// Every triangle's record, for a renderer's many hits; spheres go to Scene::surfaceAt.
class TriangleSurfaces {
public:
    explicit TriangleSurfaces(const Scene& scene);

    SurfaceHit surfaceAt(const Ray& ray, const Hit& hit) const {
        if (hit.prim >= records_.size()) return scene_.surfaceAt(ray, hit);
        return triangleSurfaceAt(records_[hit.prim], scene_.triangles.normals, hit);
    }

    size_t size() const { return records_.size(); }
    // Starts loading the record of a triangle that will be shaded soon, without waiting for it.
    void prefetch(uint32_t prim) const {
        if (prim < records_.size()) __builtin_prefetch(&records_[prim]);
    }
    const TriangleSurface& record(uint32_t prim) const { return records_[prim]; }
    const std::vector<Vec3>& vertexNormals() const { return scene_.triangles.normals; }

private:
    const Scene& scene_;
    std::vector<TriangleSurface> records_;
};

}  // namespace rtlab
