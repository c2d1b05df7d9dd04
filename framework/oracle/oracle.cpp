#include "framework/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

// Watertight ray-triangle test in double (Woop et al. 2013). The sheared coordinates of
// float vertices are computed in double, so the edge functions are far more precise than
// any float test; barycentrics come out exactly on edges as 0.
std::optional<OracleHit> intersectTriangleExact(const OracleRay& ray, const DVec3& p0, const DVec3& p1,
                                                const DVec3& p2, double edgeSlack) {
    DVec3 absDir = glm::abs(ray.direction);
    int kz = (absDir.x >= absDir.y && absDir.x >= absDir.z) ? 0 : (absDir.y >= absDir.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    double dz = ray.direction[kz];
    if (!(dz != 0.0)) return std::nullopt;  // zero or NaN direction
    double sx = ray.direction[kx] / dz, sy = ray.direction[ky] / dz, sz = 1.0 / dz;

    DVec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;
    double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
    double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
    double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
    double u = cx * by - cy * bx;  // weight of p0
    double v = ax * cy - ay * cx;  // weight of p1
    double w = bx * ay - by * ax;  // weight of p2
    double det = u + v + w;
    if (!(det != 0.0)) return std::nullopt;  // edge-on, degenerate or NaN
    double b0 = u / det, b1 = v / det, b2 = w / det;
    double margin = std::min({b0, b1, b2});
    if (!(margin >= -edgeSlack)) return std::nullopt;
    double t = (b0 * a[kz] + b1 * b[kz] + b2 * c[kz]) * sz;
    if (!(t > ray.tMin && t <= ray.tMax)) return std::nullopt;

    OracleHit hit;
    hit.hit = true;
    hit.t = t;
    hit.edgeMargin = margin;
    hit.point = b0 * p0 + b1 * p1 + b2 * p2;
    hit.normal = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    return hit;
}

// Ray-sphere in double with the discriminant computed from the ray's distance to the centre
// (Haines et al., Ray Tracing Gems ch. 7), which avoids cancellation for distant spheres.
std::optional<OracleHit> intersectSphereExact(const OracleRay& ray, const DVec3& centre, double radius) {
    double a = glm::dot(ray.direction, ray.direction);
    if (!(a > 0.0)) return std::nullopt;
    DVec3 f = ray.origin - centre;
    double bHalf = -glm::dot(f, ray.direction);  // = -b/2
    DVec3 perpendicular = f + (bHalf / a) * ray.direction;
    double discriminant = a * (radius * radius - glm::dot(perpendicular, perpendicular));
    if (!(discriminant >= 0.0)) return std::nullopt;
    double root = std::sqrt(discriminant);
    double q = bHalf + std::copysign(root, bHalf);
    double c = glm::dot(f, f) - radius * radius;
    double t0 = q / a, t1 = (q != 0.0) ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    double t = (t0 > ray.tMin && t0 <= ray.tMax) ? t0 : t1;
    if (!(t > ray.tMin && t <= ray.tMax)) return std::nullopt;
    OracleHit hit;
    hit.hit = true;
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    hit.normal = glm::normalize(hit.point - centre);
    return hit;
}

}  // namespace

std::optional<OracleHit> Oracle::intersect(uint32_t prim, const OracleRay& ray, double edgeSlack) const {
    std::optional<OracleHit> hit;
    if (scene_.isSphere(prim)) {
        const Sphere& s = scene_.sphere(prim);
        hit = intersectSphereExact(ray, DVec3(s.centre), s.radius);
    } else {
        auto v = scene_.triangleVertices(prim);
        hit = intersectTriangleExact(ray, DVec3(v[0]), DVec3(v[1]), DVec3(v[2]), edgeSlack);
    }
    if (hit) hit->prim = prim;
    return hit;
}

OracleHit Oracle::closestHit(const OracleRay& ray) const {
    OracleHit best;
    OracleRay shrinking = ray;
    for (uint32_t prim = 0; prim < scene_.primitiveCount(); ++prim) {
        auto hit = intersect(prim, shrinking);
        if (hit && (hit->t < best.t || !best.hit)) {
            best = *hit;
            shrinking.tMax = hit->t;
        }
    }
    return best;
}

bool Oracle::anyHit(const OracleRay& ray) const {
    for (uint32_t prim = 0; prim < scene_.primitiveCount(); ++prim)
        if (intersect(prim, ray)) return true;
    return false;
}

}  // namespace rtlab
