#include "framework/scene/camera.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

Ray Camera::generateRay(int i, int j, int width, int height) const {
    return generateRayThrough(i + 0.5, j + 0.5, width, height);
}

Ray Camera::generateRayThrough(double x, double y, int width, int height) const {
    return film(width, height).through(x, y);
}

void CameraFilm::throughRow(const DVec3* columns, int count, const DVec3& row, Ray* rays) const {
    constexpr int kBatch = 16;
    for (int first = 0; first < count; first += kBatch) {
        const int n = std::min(kBatch, count - first);
        // glm::normalize(v) is v * (1 / sqrt(dot(v, v))), the dot summed as (x x + y y) + z z.
        double x[kBatch], y[kBatch], z[kBatch], scale[kBatch];
        for (int i = 0; i < n; ++i) {
            x[i] = columns[first + i].x + row.x;
            y[i] = columns[first + i].y + row.y;
            z[i] = columns[first + i].z + row.z;
        }
        for (int i = 0; i < n; ++i) scale[i] = 1.0 / std::sqrt((x[i] * x[i] + y[i] * y[i]) + z[i] * z[i]);
        for (int i = 0; i < n; ++i) {
            Ray& ray = rays[first + i];
            ray = Ray{};
            ray.origin = origin;
            ray.direction = Vec3(float(x[i] * scale[i]), float(y[i] * scale[i]), float(z[i] * scale[i]));
        }
    }
}

CameraFilm Camera::film(int width, int height) const {
    // POV-Ray's construction (docs/verification.md#1-the-exporter-rtlab-export-pov): D has
    // length 0.5 / tan(yfov/2), R = aspect * normalize(D x sky) (right-handed data), U = unit
    // sky component orthogonal to D. Everything in double, as POV-Ray does; each ray is
    // rounded once to float.
    CameraFilm f;
    f.origin = Vec3(position);
    f.forward = glm::normalize(forward) * (0.5 / std::tan(yfov / 2.0));
    f.right = glm::normalize(glm::cross(f.forward, up)) * (static_cast<double>(width) / height);
    f.up = glm::normalize(glm::cross(f.right, f.forward));
    f.width = width;
    f.height = height;
    return f;
}

}  // namespace rtlab
