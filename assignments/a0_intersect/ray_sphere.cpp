// Assignment a0, part 3: robust ray-sphere.         Guide: docs/a0-intersect.md#spheres
//
// Contract (framework/interface/a0_intersect.h):
//   Return true when the ray meets the sphere at a distance t with ray.tMin < t <= tMax, and
//   write the nearest such t to *t. Rays starting inside the sphere hit its far side.
//
// Hints:
//   * Don't use b*b - 4ac directly: for a far-away sphere both terms are huge and nearly equal.
//     Compute the discriminant from the distance between the centre and the ray's closest
//     point instead.
//   * Get the two roots as q/a and c/q with q = -b/2 - sign(b) * sqrt(disc), never by
//     subtracting nearly equal numbers.
#include "framework/core/error.h"
#include "framework/interface/a0_intersect.h"

namespace rtlab {

bool intersectSphere(const Ray& ray, float tMax, const Vec3& centre, float radius, float* t) {
    (void)ray, (void)tMax, (void)centre, (void)radius, (void)t;
    throw NotImplemented("a0 intersectSphere (assignments/a0_intersect/ray_sphere.cpp)");
}

}  // namespace rtlab
