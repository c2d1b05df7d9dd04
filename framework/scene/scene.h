// A scene as the renderer and accelerators see it: every mesh flattened into one world-space
// triangle list (float32 positions, optional per-vertex normals), analytic spheres, Lambert
// materials, point lights and cameras.
//
// Primitive ids: triangles are 0 .. triangleCount()-1, spheres follow.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/scene/camera.h"
#include "framework/scene/light.h"
#include "framework/scene/material.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

struct Triangles {
    std::vector<Vec3> positions;                   // world space
    std::vector<Vec3> normals;                     // per vertex; empty when no mesh has normals
    std::vector<std::array<uint32_t, 3>> indices;  // into positions (and normals)
    std::vector<uint32_t> material;                // per triangle
    std::vector<uint8_t> smooth;                   // per triangle: interpolate vertex normals
};

struct Sphere {
    Vec3 centre{0.0f};
    float radius = 1.0f;
    uint32_t material = 0;
};

// The surface at a hit: what shading needs.
struct SurfaceHit {
    Vec3 point;
    Vec3 geometricNormal;  // unit, not flipped
    Vec3 shadingNormal;    // unit; interpolated when the mesh has normals
    Vec3 pointError;       // conservative bound on the rounding error of point (for offsets)
    uint32_t material = 0;
    uint32_t prim = kNoHit;  // the primitive hit
};

struct Scene {
    std::string sourcePath;
    Triangles triangles;
    std::vector<Sphere> spheres;
    std::vector<Material> materials;
    std::vector<PointLight> lights;
    std::vector<Camera> cameras;
    std::vector<std::string> featuresUsed;  // glTF extensions and rtlab extras met while loading

    uint32_t triangleCount() const { return static_cast<uint32_t>(triangles.indices.size()); }
    uint32_t primitiveCount() const {
        return triangleCount() + static_cast<uint32_t>(spheres.size());
    }
    bool isSphere(uint32_t prim) const { return prim >= triangleCount(); }
    const Sphere& sphere(uint32_t prim) const { return spheres[prim - triangleCount()]; }
    std::array<Vec3, 3> triangleVertices(uint32_t prim) const {
        const auto& idx = triangles.indices[prim];
        return {triangles.positions[idx[0]], triangles.positions[idx[1]], triangles.positions[idx[2]]};
    }

    Bounds3f primitiveBounds(uint32_t prim) const;
    Bounds3f bounds() const;
    uint32_t materialOf(uint32_t prim) const;
    SurfaceHit surfaceAt(const Ray& ray, const Hit& hit) const;

    // Finds a camera by name; throws rtlab::Error listing the available names.
    const Camera& camera(const std::string& name) const;
};

}  // namespace rtlab
