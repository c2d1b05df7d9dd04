#include "framework/scene/scene.h"

#include "framework/core/error.h"
#include "framework/core/float_bits.h"

#include <cmath>

namespace rtlab {

Bounds3f Scene::primitiveBounds(uint32_t prim) const {
    if (isSphere(prim)) {
        const Sphere& s = sphere(prim);
        return Bounds3f(s.centre - Vec3(s.radius), s.centre + Vec3(s.radius));
    }
    auto v = triangleVertices(prim);
    Bounds3f b(v[0]);
    b.extend(v[1]);
    b.extend(v[2]);
    return b;
}

Bounds3f Scene::bounds() const {
    Bounds3f b;
    for (uint32_t i = 0; i < primitiveCount(); ++i) b.extend(primitiveBounds(i));
    return b;
}

uint32_t Scene::materialOf(uint32_t prim) const {
    return isSphere(prim) ? sphere(prim).material : triangles.material[prim];
}

SurfaceHit Scene::surfaceAt(const Ray& ray, const Hit& hit) const {
    SurfaceHit s;
    s.material = materialOf(hit.prim);
    s.prim = hit.prim;
    if (isSphere(hit.prim)) {
        const Sphere& sp = sphere(hit.prim);
        Vec3 p = ray.at(hit.t);
        Vec3 n = glm::normalize(p - sp.centre);
        // Re-project onto the sphere: the error is then a few ulps of the radius (pbrt-v4 6.8.5).
        s.point = sp.centre + sp.radius * n;
        s.pointError = gamma(5) * glm::abs(s.point);
        s.geometricNormal = n;
        s.shadingNormal = n;
        return s;
    }
    auto v = triangleVertices(hit.prim);
    float b0 = 1.0f - hit.b1 - hit.b2;
    // Reconstructing the point from barycentrics bounds its error (pbrt-v4 6.8.5).
    s.point = b0 * v[0] + hit.b1 * v[1] + hit.b2 * v[2];
    s.pointError = gamma(7) * (glm::abs(b0 * v[0]) + glm::abs(hit.b1 * v[1]) + glm::abs(hit.b2 * v[2]));
    Vec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    float length = glm::length(n);
    s.geometricNormal = length > 0.0f ? n / length : Vec3(0.0f, 0.0f, 1.0f);
    s.shadingNormal = s.geometricNormal;
    if (triangles.smooth[hit.prim]) {
        const auto& idx = triangles.indices[hit.prim];
        Vec3 ns = b0 * triangles.normals[idx[0]] + hit.b1 * triangles.normals[idx[1]] +
                  hit.b2 * triangles.normals[idx[2]];
        float ls = glm::length(ns);
        if (ls > 0.0f) s.shadingNormal = ns / ls;
    }
    return s;
}

const Camera& Scene::camera(const std::string& name) const {
    if (cameras.empty()) throw Error(sourcePath + ": the scene has no camera");
    if (name.empty()) return cameras.front();
    std::string available;
    for (const Camera& c : cameras) {
        if (c.name == name) return c;
        available += (available.empty() ? "" : ", ") + ("'" + c.name + "'");
    }
    throw Error(sourcePath + ": no camera named '" + name + "' (available: " + available + ")");
}

}  // namespace rtlab
