// Assignment a0 (docs/a0-intersect.md): the three ray-primitive tests everything else rests on.
// Implemented in assignments/a0_intersect/ (yours) and solutions/a0_intersect/ (reference).
//
// Shared contract (docs/conventions.md):
//  * a hit at distance t counts when tMin < t <= tMax (both ends given by the caller);
//  * points on edges, vertices and box faces count as hits;
//  * NaN anywhere (vertex, origin, direction) never produces a hit;
//  * direction components may be +0.0 or -0.0; -0.0 behaves like a negative direction.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"

namespace rtlab {

// Slab test. True when the segment (tMin, tMax] of the ray overlaps the closed box; then
// *tEnter is where the ray enters the box (clamped to tMin). Conservative: the far distance is
// enlarged by 1 + 2*gamma(3) so rounding never loses a box the ray really touches.
bool intersectBox(const Bounds3f& box, const RayInverse& ray, float tMin, float tMax, float* tEnter);

struct TriangleHit {
    float t;
    float b1;  // barycentric weight of p1
    float b2;  // barycentric weight of p2 (p0 gets 1 - b1 - b2)
};

// Watertight ray-triangle test (Woop, Benthin, Wald 2013), two-sided. True when the ray hits
// the triangle at some t with ray.tMin < t <= tMax; then fills *hit.
bool intersectTriangle(const Ray& ray, float tMax, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       TriangleHit* hit);

// Ray-sphere test, numerically robust for distant and grazing rays. True when the nearest
// intersection with ray.tMin < t <= tMax exists; then writes it to *t.
bool intersectSphere(const Ray& ray, float tMax, const Vec3& centre, float radius, float* t);

}  // namespace rtlab
