// Secondary rays that cannot hit the surface they start on, without a fixed epsilon
// (pbrt-v4 §6.8.6, Wächter & Binder, Ray Tracing Gems ch. 6): the origin moves off the
// surface along the geometric normal by the hit point's rounding-error bound, then one more
// float step away, so the true surface lies behind it. (A point without rounding error, such
// as one on the plane y = 0, stays where it is: it is exact.)
#pragma once

#include "framework/core/float_bits.h"
#include "framework/core/ray.h"

namespace rtlab {

// Shadow rays ignore this fraction of their length at both ends (pbrt-v4's ShadowEpsilon).
// At the light end it keeps geometry the light sits on from shadowing it. At the surface end it
// guards against the float triangle test itself: the a0 contract does not ask for pbrt's
// conservative "t > error bound" check, so a ray leaving a plane whose offset is zero (a floor
// at y = 0 has no rounding error in y) re-hits that plane at t = +-1e-8 about half the time,
// which shows as speckled self-shadowing. POV-Ray trims 1e-3 scene units at both ends.
inline constexpr float kShadowEpsilon = 1e-4f;

// Moves p, whose components are off by at most pointError, to the side of the plane with
// normal n that w points into.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pointError, const Vec3& n, const Vec3& w) {
    float distance = glm::dot(glm::abs(n), pointError);
    Vec3 offset = distance * n;
    if (glm::dot(w, n) < 0.0f) offset = -offset;
    Vec3 origin = p + offset;
    for (int axis = 0; axis < 3; ++axis) origin[axis] = floatStep(origin[axis], offset[axis]);
    return origin;
}

// A shadow ray from a surface point towards `target`. Its direction is target - origin, so
// t = 1 is the target and the occluders that count lie in (kShadowEpsilon, 1 - kShadowEpsilon].
inline Ray spawnShadowRay(const Vec3& p, const Vec3& pointError, const Vec3& geometricNormal,
                          const Vec3& target) {
    Ray ray;
    ray.origin = offsetRayOrigin(p, pointError, geometricNormal, target - p);
    ray.direction = target - ray.origin;
    ray.tMin = kShadowEpsilon;
    ray.tMax = 1.0f - kShadowEpsilon;
    return ray;
}

}  // namespace rtlab
