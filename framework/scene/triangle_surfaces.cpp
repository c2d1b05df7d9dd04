#include "framework/scene/triangle_surfaces.h"

#include "framework/core/float_bits.h"

namespace rtlab {

TriangleSurface gatherTriangleSurface(const Scene& scene, uint32_t prim) {
    const Triangles& triangles = scene.triangles;
    TriangleSurface record;
    record.corners = scene.triangleVertices(prim);
    const auto& [v0, v1, v2] = record.corners;
    Vec3 n = glm::cross(v1 - v0, v2 - v0);
    float length = glm::length(n);
    record.faceNormal = length > 0.0f ? n / length : Vec3(0.0f, 0.0f, 1.0f);
    record.normals = triangles.smooth[prim] ? triangles.indices[prim] : std::array{kFlatTriangle, 0u, 0u};
    record.material = triangles.material[prim];
    return record;
}

SurfaceHit triangleSurfaceAt(const TriangleSurface& triangle, const std::vector<Vec3>& vertexNormals,
                             const Hit& hit) {
    const auto& [v0, v1, v2] = triangle.corners;
    SurfaceHit s;
    s.material = triangle.material;
    s.prim = hit.prim;
    float b0 = 1.0f - hit.b1 - hit.b2;
    // Rebuilding the point from the barycentrics bounds its error (pbrt-v4 6.8.5).
    s.point = b0 * v0 + hit.b1 * v1 + hit.b2 * v2;
    s.pointError = gamma(7) * (glm::abs(b0 * v0) + glm::abs(hit.b1 * v1) + glm::abs(hit.b2 * v2));
    s.geometricNormal = triangle.faceNormal;
    s.shadingNormal = triangle.faceNormal;
    if (triangle.smooth()) {
        const auto& [n0, n1, n2] = triangle.normals;
        Vec3 ns = b0 * vertexNormals[n0] + hit.b1 * vertexNormals[n1] + hit.b2 * vertexNormals[n2];
        float length = glm::length(ns);
        if (length > 0.0f) s.shadingNormal = ns / length;
    }
    return s;
}

TriangleSurfaces::TriangleSurfaces(const Scene& scene) : scene_(scene) {
    records_.reserve(scene.triangleCount());
    for (uint32_t prim = 0; prim < scene.triangleCount(); ++prim) records_.push_back(gatherTriangleSurface(scene, prim));
}

}  // namespace rtlab
