#include "framework/scene/scene.h"

#include "framework/core/error.h"
#include "framework/core/float_bits.h"
#include "framework/scene/triangle_surfaces.h"

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
    if (!isSphere(hit.prim)) return triangleSurfaceAt(gatherTriangleSurface(*this, hit.prim), triangles.normals, hit);
    const Sphere& sp = sphere(hit.prim);
    SurfaceHit s;
    s.material = sp.material;
    s.prim = hit.prim;
    Vec3 n = glm::normalize(ray.at(hit.t) - sp.centre);
    // Re-project onto the sphere: the error is then a few ulps of the radius (pbrt-v4 6.8.5).
    s.point = sp.centre + sp.radius * n;
    s.pointError = gamma(5) * glm::abs(s.point);
    s.geometricNormal = n;
    s.shadingNormal = n;
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
