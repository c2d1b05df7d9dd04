#include "framework/scene/camera.h"

#include <cmath>

namespace rtlab {

Ray Camera::generateRay(int i, int j, int width, int height) const {
    return generateRayThrough(i + 0.5, j + 0.5, width, height);
}

Ray Camera::generateRayThrough(double x, double y, int width, int height) const {
    // POV-Ray's construction (docs/verification.md#1-the-exporter-rtlab-export-pov): D has
    // length 0.5 / tan(yfov/2), R = aspect * normalize(D x sky) (right-handed data), U = unit
    // sky component orthogonal to D. Everything in double, as POV-Ray does, then rounded once
    // to float.
    double aspect = static_cast<double>(width) / height;
    DVec3 d = glm::normalize(forward) * (0.5 / std::tan(yfov / 2.0));
    DVec3 r = glm::normalize(glm::cross(d, up)) * aspect;
    DVec3 u = glm::normalize(glm::cross(r, d));
    double x0 = x / width - 0.5;
    double y0 = 0.5 - y / height;
    DVec3 direction = glm::normalize(d + x0 * r + y0 * u);
    Ray ray;
    ray.origin = Vec3(position);
    ray.direction = Vec3(direction);
    return ray;
}

}  // namespace rtlab
