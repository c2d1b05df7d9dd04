#include "framework/scene/camera.h"

#include <cmath>

namespace rtlab {

Ray Camera::generateRay(int i, int j, int width, int height) const {
    return generateRayThrough(i + 0.5, j + 0.5, width, height);
}

Ray Camera::generateRayThrough(double x, double y, int width, int height) const {
    return film(width, height).through(x, y);
}

CameraFilm Camera::film(int width, int height) const {
    // POV-Ray's construction (docs/verification.md#1-the-exporter-rtlab-export-pov): D has
    // length 0.5 / tan(yfov/2), R = aspect * normalize(D x sky) (right-handed data), U = unit
    // sky component orthogonal to D. Everything in double, as POV-Ray does; each ray is
    // rounded once to float.
    CameraFilm f;
    f.origin = position;
    f.forward = glm::normalize(forward) * (0.5 / std::tan(yfov / 2.0));
    f.right = glm::normalize(glm::cross(f.forward, up)) * (static_cast<double>(width) / height);
    f.up = glm::normalize(glm::cross(f.right, f.forward));
    f.width = width;
    f.height = height;
    return f;
}

}  // namespace rtlab
