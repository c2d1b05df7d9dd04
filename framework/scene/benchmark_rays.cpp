// Compiled with -ffp-contract=off: the rays must come out bit for bit as the reference page
// specifies, and a fused multiply-add changes the last bits.
#include "framework/scene/benchmark_rays.h"

#include "framework/core/error.h"
#include "framework/core/fnv1a.h"
#include "framework/core/pcg32.h"

#include <cmath>
#include <numbers>

namespace rtlab {

BenchmarkView::BenchmarkView(const Bounds3f& bounds) {
    Vec3 centre = 0.5f * (bounds.lower + bounds.upper);
    float radius = 0.5f * glm::length(bounds.upper - bounds.lower);
    eye = centre + glm::normalize(Vec3(0.6f, 0.5f, 1.0f)) * (2.0f * radius);
    forward = glm::normalize(centre - eye);
    right = glm::normalize(glm::cross(forward, Vec3(0.0f, 1.0f, 0.0f)));
    up = glm::cross(right, forward);
    tanHalfFov = std::tan(std::numbers::pi_v<float> / 8.0f);
}

Camera BenchmarkView::camera() const {
    Camera camera;
    camera.position = DVec3(eye);
    camera.forward = DVec3(forward);
    camera.up = DVec3(up);
    camera.yfov = std::numbers::pi / 4.0;
    camera.aspectRatio = 1.0;
    return camera;
}

std::vector<Ray> makePrimaryRays(const Bounds3f& bounds, int resolution) {
    BenchmarkView view(bounds);
    auto size = static_cast<float>(resolution);
    std::vector<Ray> rays;
    rays.reserve(static_cast<size_t>(resolution) * resolution);
    for (int y = 0; y < resolution; ++y) {
        for (int x = 0; x < resolution; ++x) {
            float u = (2.0f * (static_cast<float>(x) + 0.5f) / size - 1.0f) * view.tanHalfFov;
            float v = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / size) * view.tanHalfFov;
            Ray ray;
            ray.origin = view.eye;
            ray.direction = glm::normalize(view.forward + u * view.right + v * view.up);
            rays.push_back(ray);
        }
    }
    return rays;
}

std::vector<Ray> makeIncoherentRays(const Bounds3f& bounds, uint32_t count) {
    Pcg32 rng(1234, 54);
    Vec3 extent = bounds.upper - bounds.lower;
    std::vector<Ray> rays;
    rays.reserve(count);
    for (uint32_t i = 0; i < count; ++i) {
        Vec3 u;
        for (int axis = 0; axis < 3; ++axis) u[axis] = rng.uniform();
        float z = 1.0f - 2.0f * rng.uniform();
        float phi = 2.0f * std::numbers::pi_v<float> * rng.uniform();
        float r = std::sqrt(1.0f - z * z);
        Ray ray;
        ray.origin = bounds.lower + extent * u;
        ray.direction = Vec3(r * std::cos(phi), r * std::sin(phi), z);
        rays.push_back(ray);
    }
    return rays;
}

RayKind parseRayKind(const std::string& name) {
    if (name == "primary") return RayKind::Primary;
    if (name == "incoherent") return RayKind::Incoherent;
    throw Error("'" + name + "' is not a ray set (valid: primary, incoherent)");
}

const char* rayKindName(RayKind kind) { return kind == RayKind::Primary ? "primary" : "incoherent"; }

std::vector<Ray> makeBenchmarkRays(RayKind kind, const Bounds3f& bounds) {
    return kind == RayKind::Primary ? makePrimaryRays(bounds) : makeIncoherentRays(bounds);
}

uint64_t rayChecksum(std::span<const Ray> rays) {
    uint64_t hash = kFnv1aOffsetBasis;
    for (const Ray& ray : rays) {
        float record[6] = {ray.origin.x, ray.origin.y, ray.origin.z,
                           ray.direction.x, ray.direction.y, ray.direction.z};
        hash = fnv1a64(record, sizeof record, hash);
    }
    return hash;
}

}  // namespace rtlab
