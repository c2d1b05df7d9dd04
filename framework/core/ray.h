// A ray and the valid parameter interval of the hits it accepts.
//
// Convention (docs/conventions.md): a hit at distance t counts when tMin < t <= tMax.
#pragma once

#include "framework/core/vec.h"

#include <array>
#include <cmath>

namespace rtlab {

struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, 1.0f};  // need not be unit length; t is measured in its units
    float tMin = 0.0f;
    float tMax = kInfinity;

    Vec3 at(float t) const { return origin + t * direction; }
};

// What a slab test needs per ray, computed once per query by the framework: the reciprocal
// direction and which direction components are negative. std::signbit treats -0.0 as
// negative, matching 1/-0.0 = -inf, so the near plane is always picked consistently.
struct RayInverse {
    Vec3 origin;
    Vec3 invDirection;
    std::array<int, 3> dirIsNegative;

    explicit RayInverse(const Ray& ray)
        : origin(ray.origin),
          invDirection(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z),
          dirIsNegative{std::signbit(ray.direction.x) ? 1 : 0, std::signbit(ray.direction.y) ? 1 : 0,
                        std::signbit(ray.direction.z) ? 1 : 0} {}
};

}  // namespace rtlab
