// The exact oracle: a double-precision brute-force intersector over a scene. It shares no code
// with any student file or accelerator, so it can judge them. Float inputs (vertices, rays) are
// widened to double exactly; only the intersection arithmetic is in double.
#pragma once

#include "framework/scene/scene.h"

#include <optional>
#include <vector>

namespace rtlab {

struct OracleRay {
    DVec3 origin;
    DVec3 direction;
    double tMin = 0.0;
    double tMax = std::numeric_limits<double>::infinity();

    static OracleRay from(const Ray& ray) {
        return {DVec3(ray.origin), DVec3(ray.direction), ray.tMin, ray.tMax};
    }
};

struct OracleHit {
    bool hit = false;
    double t = std::numeric_limits<double>::infinity();
    uint32_t prim = kNoHit;
    // Smallest barycentric coordinate of the hit (0 on an edge); 1 for spheres. Lets a grader
    // tell rays that graze an edge from clear hits.
    double edgeMargin = 1.0;
    DVec3 point{0.0};
    DVec3 normal{0.0};  // geometric, unit, as stored (not flipped toward the ray)
};

class Oracle {
public:
    explicit Oracle(const Scene& scene) : scene_(scene) {}

    // Closest hit with tMin < t <= tMax; on equal t the lowest primitive id wins.
    OracleHit closestHit(const OracleRay& ray) const;
    // Any hit with tMin < t <= tMax.
    bool anyHit(const OracleRay& ray) const;
    // Intersection of the ray with one primitive. edgeSlack >= 0 also accepts triangle hits up
    // to that far outside an edge, in barycentric units.
    std::optional<OracleHit> intersect(uint32_t prim, const OracleRay& ray, double edgeSlack = 0.0) const;

private:
    const Scene& scene_;
};

}  // namespace rtlab
