#include "framework/accel/primitive_set.h"

#include "framework/interface/traversal.h"

#include "framework/interface/a0_intersect.h"

namespace rtlab {

PrimitiveSet::PrimitiveSet(const Scene& scene) : spheres_(scene.spheres) {
    triangles_.reserve(scene.triangleCount());
    for (uint32_t i = 0; i < scene.triangleCount(); ++i) triangles_.push_back(scene.triangleVertices(i));
    bounds_.reserve(scene.primitiveCount());
    for (uint32_t i = 0; i < scene.primitiveCount(); ++i) bounds_.push_back(scene.primitiveBounds(i));
}

bool PrimitiveSet::intersect(uint32_t prim, const Ray& ray, Hit& hit) const {
    if (prim < triangles_.size()) {
        const auto& v = triangles_[prim];
        TriangleHit th;
        if (!intersectTriangle(ray, hit.t, v[0], v[1], v[2], &th)) return false;
        hit = Hit{th.t, prim, th.b1, th.b2};
        return true;
    }
    const Sphere& s = spheres_[prim - triangles_.size()];
    float t;
    if (!intersectSphere(ray, hit.t, s.centre, s.radius, &t)) return false;
    hit = Hit{t, prim, 0.0f, 0.0f};
    return true;
}

// The traversal context's primitive test (framework/interface/traversal.h), here so the
// compiler inlines PrimitiveSet::intersect into it: one call per test from any traversal.
bool intersectPrimitive(const PrimitiveSet& primitives, uint32_t prim, const Ray& ray, Hit& hit) {
    return primitives.intersect(prim, ray, hit);
}

}  // namespace rtlab
