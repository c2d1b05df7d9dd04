// Vector types. Geometry is float32 (GLM's vec3); the oracle works in double (dvec3). Vec2
// holds a pair of uniform random numbers for the samplers.
#pragma once

#include <glm/glm.hpp>

#include <limits>

namespace rtlab {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using DVec3 = glm::dvec3;

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline float component(const Vec3& v, int axis) { return v[axis]; }

// Index of the largest component (ties go to the lower axis).
inline int maxComponentIndex(const Vec3& v) {
    return (v.x >= v.y && v.x >= v.z) ? 0 : (v.y >= v.z ? 1 : 2);
}

}  // namespace rtlab
