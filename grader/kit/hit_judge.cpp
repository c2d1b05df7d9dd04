#include "grader/kit/hit_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rtlab::grader {

std::string describeRay(const Ray& ray) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, "o=(%.9g, %.9g, %.9g) d=(%.9g, %.9g, %.9g)", ray.origin.x, ray.origin.y,
                  ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z);
    std::string s = buffer;
    if (ray.tMin != 0.0f || std::isfinite(ray.tMax)) {
        std::snprintf(buffer, sizeof buffer, " t in (%.9g, %.9g]", ray.tMin, ray.tMax);
        s += buffer;
    }
    return s;
}

namespace {

// Beyond this the ray is so nearly in the triangle's plane that any answer is plausible.
constexpr double kMaxRoundingSlack = 1.0;

std::string formatT(double t) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.9g", t);
    return buffer;
}

}  // namespace

namespace {

// How far outside a triangle (in barycentric units) a float watertight test may still find a
// hit, or inside it a miss, whatever order of rounding it uses (t = x / det or x * (1 / det),
// fused or not): its edge functions are products of lateral vertex coordinates that carry the
// rounding of the translation and the shear, a few ulps of |v| + |o|, and they are divided by
// det, twice the triangle's area as the ray sees it, which is small for grazing rays.
double roundingSlack(const std::array<Vec3, 3>& v, const OracleRay& ray) {
    DVec3 direction = glm::normalize(ray.direction);
    double scale = 0.0, lateral = 0.0;
    std::array<DVec3, 3> p;
    for (int i = 0; i < 3; ++i) {
        p[i] = DVec3(v[i]) - ray.origin;
        scale = std::max(scale, glm::length(DVec3(v[i])) + glm::length(ray.origin));
        lateral += glm::length(p[i] - glm::dot(p[i], direction) * direction);
    }
    double det = std::abs(glm::dot(direction, glm::cross(p[1] - p[0], p[2] - p[0])));
    constexpr double kUlps = 8.0 * 0x1p-24;
    return det > 0.0 ? kUlps * scale * lateral / det : std::numeric_limits<double>::infinity();
}

}  // namespace

// Every primitive the oracle finds on the ray (with the edge slack), with the tolerance a
// float implementation is allowed on its distance: a few ulps of the quantities involved,
// divided by how obliquely the ray meets the surface.
std::vector<HitJudge::Candidate> HitJudge::findCandidates(const Ray& ray) const {
    std::vector<Candidate> found;
    OracleRay exact = OracleRay::from(ray);
    exact.tMax = std::numeric_limits<double>::infinity();
    double length = glm::length(exact.direction);
    if (!(length > 0) || !std::isfinite(length)) return found;
    double originScale = glm::length(exact.origin) / length;
    for (uint32_t prim = 0; prim < scene_.primitiveCount(); ++prim) {
        double rounding = scene_.isSphere(prim) ? 0.0 : roundingSlack(scene_.triangleVertices(prim), exact);
        auto hit = oracle_.intersect(prim, exact, kEdgeSlack + std::min(rounding, kMaxRoundingSlack));
        if (!hit) continue;
        Candidate c{prim, hit->t, 0.0, false};
        if (scene_.isSphere(prim)) {
            const Sphere& s = scene_.sphere(prim);
            DVec3 f = exact.origin - DVec3(s.centre);
            DVec3 perpendicular = f - glm::dot(f, exact.direction) / (length * length) * exact.direction;
            double margin = 1.0 - glm::dot(perpendicular, perpendicular) / (double(s.radius) * s.radius);
            c.robust = margin >= 1e-3;
            c.tolerance = 1e-5 * (std::abs(hit->t) + glm::length(f) / length + s.radius / length) /
                          std::sqrt(std::max(margin, 1e-6));
        } else {
            double cosine = std::abs(glm::dot(hit->normal, exact.direction)) / length;
            auto v = scene_.triangleVertices(prim);
            double size = glm::length(DVec3(v[1] - v[0])) + glm::length(DVec3(v[2] - v[0]));
            c.robust = hit->edgeMargin >= std::max(kRobustMargin, rounding);
            c.tolerance = 1e-6 * std::abs(hit->t) +
                          4e-6 * (std::abs(hit->t) + originScale + size / length) / std::max(cosine, 1e-4);
        }
        found.push_back(c);
    }
    return found;
}

const std::vector<HitJudge::Candidate>& HitJudge::candidates(size_t index, const Ray& ray) {
    if (!cache_.at(index)) cache_[index] = findCandidates(ray);
    return *cache_[index];
}

std::optional<HitJudge::Candidate> HitJudge::closestCandidate(size_t index, const Ray& ray) {
    std::optional<Candidate> best;
    for (const Candidate& c : candidates(index, ray))
        if (c.t > ray.tMin && c.t <= ray.tMax && (!best || c.t < best->t)) best = c;
    return best;
}

namespace {

template <typename Candidates>
std::string expectation(const Candidates& all, double tRequired) {
    if (!std::isfinite(tRequired)) return "expected a miss (or a grazing hit)";
    std::string ids;
    int listed = 0;
    for (const auto& c : all)
        if (std::abs(c.t - tRequired) <= c.tolerance && listed++ < 6) {
            if (!ids.empty()) ids += ',';
            ids += std::to_string(c.prim);
        }
    return "expected a hit at t=" + formatT(tRequired) + (ids.empty() ? "" : " on prim {" + ids + "}");
}

}  // namespace

std::string HitJudge::judgeClosest(size_t index, const Ray& ray, bool mustHit, const HitAnswer& answer) {
    const auto& all = candidates(index, ray);
    // The answer may not lie beyond a robust hit; a ray known to cross a surface must hit
    // something, whichever of the (near-)tied primitives at the crossing it reports.
    double tRobust = std::numeric_limits<double>::infinity(), robustTolerance = 0.0;
    for (const Candidate& c : all)
        if (c.robust && c.t < tRobust) {
            tRobust = c.t;
            robustTolerance = c.tolerance;
        }
    double tExpected = tRobust;
    if (mustHit)
        for (const Candidate& c : all) tExpected = std::min(tExpected, c.t);
    if (answer.prim == kNoHit) {
        if (!std::isfinite(tExpected)) return "";
        return expectation(all, tExpected) + ", got a miss";
    }
    std::string got = ", got prim " + std::to_string(answer.prim) + " at t=" + formatT(answer.t);
    auto match = std::find_if(all.begin(), all.end(), [&](const Candidate& c) {
        return c.prim == answer.prim && std::abs(c.t - double(answer.t)) <= c.tolerance;
    });
    if (match == all.end()) {
        std::string why = answer.prim < scene_.primitiveCount() ? " (that primitive is not hit there)" : " (no such primitive)";
        return expectation(all, tExpected) + got + why;
    }
    if (double(answer.t) > tRobust + robustTolerance + match->tolerance)
        return expectation(all, tRobust) + got + " (a closer hit was missed)";
    if (!(answer.t > ray.tMin && answer.t <= ray.tMax)) return "a hit must satisfy tMin < t <= tMax" + got;
    return "";
}

std::string HitJudge::judgeOccluded(size_t index, const Ray& ray, bool mustHit, bool occluded) {
    const auto& all = candidates(index, ray);
    bool anyPossible = false, required = false;
    for (const Candidate& c : all) {
        if (c.t - c.tolerance <= ray.tMax) anyPossible = true;
        if ((c.robust || mustHit) && c.t + c.tolerance <= ray.tMax) required = true;
    }
    if (occluded && !anyPossible) return "expected not occluded (nothing in the segment), got occluded";
    if (!occluded && required) return "expected occluded (a primitive blocks the segment), got not occluded";
    return "";
}

}  // namespace rtlab::grader
