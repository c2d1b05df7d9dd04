// Judges a student's answers ray by ray against the exact oracle (docs/grading.md, "Hit
// sets"). A closest hit is right when it is a real intersection of the primitive it names
// (within the edge slack and t tolerance) and no primitive is robustly hit before it; a miss
// is right when nothing is robustly hit. "Robustly" means at least kRobustMargin inside a
// triangle's edges (or off a sphere's silhouette), so grazing rays decided by rounding accept
// either answer, while rays known to cross a surface must hit.
#pragma once

#include "framework/core/ray.h"
#include "framework/oracle/oracle.h"
#include "framework/scene/scene.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::grader {

inline constexpr double kEdgeSlack = 1e-4;     // barycentric units
inline constexpr double kRobustMargin = 1e-4;  // barycentric units (spheres: 1 - d^2/r^2 >= 1e-3)

// What a child reports for one closest-hit query: raw values only.
struct HitAnswer {
    uint32_t prim = kNoHit;
    float t = 0.0f;
};

class HitJudge {
public:
    // The judge of one ray set: rays[i] and the any-hit variant of ray i share origin,
    // direction and tMin, so the oracle runs once per ray index and is cached.
    HitJudge(const Scene& scene, size_t rayCount) : scene_(scene), oracle_(scene), cache_(rayCount) {}

    // Empty when the answer is acceptable, else what was expected and what came back.
    std::string judgeClosest(size_t index, const Ray& ray, bool mustHit, const HitAnswer& answer);
    std::string judgeOccluded(size_t index, const Ray& ray, bool mustHit, bool occluded);

    // A primitive the ray meets (within the edge slack), at t (without the ray's tMax), with the
    // distance tolerance a float test is allowed; robust when the crossing is clear of its edges.
    struct Candidate {
        uint32_t prim;
        double t;
        double tolerance;
        bool robust;
    };
    // Every candidate of ray `index` (computed once, then cached).
    const std::vector<Candidate>& candidates(size_t index, const Ray& ray);
    // The oracle's closest hit of ray `index` in (tMin, tMax], or nothing: what a viewer shows as
    // the expected answer (the judge itself accepts any tied primitive).
    std::optional<Candidate> closestCandidate(size_t index, const Ray& ray);

private:
    std::vector<Candidate> findCandidates(const Ray& ray) const;

    const Scene& scene_;
    Oracle oracle_;
    std::vector<std::optional<std::vector<Candidate>>> cache_;
};

std::string describeRay(const Ray& ray);

}  // namespace rtlab::grader
