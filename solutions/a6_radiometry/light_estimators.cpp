// Reference solution: direct light from one light, by sampling the light's area or the solid
// angle it subtends (docs/a6-radiometry.md#estimators).
#include "framework/interface/a6_radiometry.h"
#include "reflected_radiance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtlab {
namespace {

// The shadow ray is cast last, and only for a sample that would contribute.
Vec3 ifVisible(const Vec3& value, const Vec3& lightPoint, const SceneRays& rays) {
    if (value == Vec3(0.0f) || !rays.visible(lightPoint)) return Vec3(0.0f);
    return value;
}

}  // namespace

Vec3 estimatePointLight(const ShadingPoint& x, const PointEmitter& light, const SceneRays& rays) {
    Vec3 toLight = light.position - x.position;
    float distanceSquared = glm::dot(toLight, toLight);
    float cosX = glm::dot(x.normal, toLight) / std::sqrt(distanceSquared);
    if (!(cosX > 0.0f)) return Vec3(0.0f);
    // I dOmega over a patch at distance d: the inverse-square law, no sampling needed.
    Vec3 value = x.albedo * std::numbers::inv_pi_v<float> * light.intensity * (cosX / distanceSquared);
    return ifVisible(value, light.position, rays);
}

Vec3 estimateTriangleLightByArea(const ShadingPoint& x, const TriangleEmitter& light, Vec2 u, const SceneRays& rays) {
    PointSample y = sampleUniformTriangle(light.p0, light.p1, light.p2, u);
    Vec3 toLight = y.point - x.position;
    float distanceSquared = glm::dot(toLight, toLight);
    Vec3 w = toLight / std::sqrt(distanceSquared);
    Vec3 front = glm::normalize(glm::cross(light.p1 - light.p0, light.p2 - light.p0));
    // Positive when the front face looks at x.
    float cosLight = -glm::dot(front, w);
    if (!light.twoSided && !(cosLight > 0.0f)) return Vec3(0.0f);
    float pdf = areaToSolidAnglePdf(y.pdf, distanceSquared, cosLight);
    return ifVisible(reflectedRadiance(x, light.radiance, w, pdf), y.point, rays);
}

Vec3 estimateTriangleLightBySolidAngle(const ShadingPoint& x, const TriangleEmitter& light, Vec2 u, const SceneRays& rays) {
    DirectionSample s = sampleSphericalTriangle(x.position, light.p0, light.p1, light.p2, u);
    Vec3 normal = glm::cross(light.p1 - light.p0, light.p2 - light.p0);
    float normalDotW = glm::dot(normal, s.direction);
    // Arriving at the front face means travelling against its normal; a direction in the plane
    // sees no area at all.
    if (normalDotW == 0.0f || (!light.twoSided && !(normalDotW < 0.0f))) return Vec3(0.0f);
    float t = glm::dot(normal, light.p0 - x.position) / normalDotW;
    Vec3 lightPoint = x.position + t * s.direction;
    return ifVisible(reflectedRadiance(x, light.radiance, s.direction, s.pdf), lightPoint, rays);
}

Vec3 estimateSphereLightByArea(const ShadingPoint& x, const SphereEmitter& light, Vec2 u, const SceneRays& rays) {
    Vec3 outward = sampleUniformSphere(u).direction;
    Vec3 y = light.centre + light.radius * outward;
    Vec3 toLight = y - x.position;
    float distanceSquared = glm::dot(toLight, toLight);
    Vec3 w = toLight / std::sqrt(distanceSquared);
    // Only the cap facing x is seen from x; the rest of the sphere turns its back to it.
    float cosLight = -glm::dot(outward, w);
    if (!(cosLight > 0.0f)) return Vec3(0.0f);
    float pdfArea = 1.0f / (4.0f * std::numbers::pi_v<float> * light.radius * light.radius);
    float pdf = areaToSolidAnglePdf(pdfArea, distanceSquared, cosLight);
    return ifVisible(reflectedRadiance(x, light.radiance, w, pdf), y, rays);
}

Vec3 estimateSphereLightBySolidAngle(const ShadingPoint& x, const SphereEmitter& light, Vec2 u, const SceneRays& rays) {
    Vec3 toCentre = light.centre - x.position;
    float distanceSquared = glm::dot(toCentre, toCentre);
    float distance = std::sqrt(distanceSquared);
    if (!(distance > light.radius)) return Vec3(0.0f);
    float sin2Max = light.radius * light.radius / distanceSquared;
    DirectionSample local = sampleUniformCone(u, std::sqrt(std::max(0.0f, 1.0f - sin2Max)));
    Vec3 w = Frame(toCentre / distance).toWorld(local.direction);
    // Where the ray first meets the sphere: the nearer root of |x + t w - centre| = radius.
    float cosTheta = local.direction.z;
    float sin2 = std::max(0.0f, 1.0f - cosTheta * cosTheta);
    float t = distance * cosTheta - std::sqrt(std::max(0.0f, light.radius * light.radius - distanceSquared * sin2));
    return ifVisible(reflectedRadiance(x, light.radiance, w, local.pdf), x.position + t * w, rays);
}

}  // namespace rtlab
