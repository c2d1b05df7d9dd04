// Hit sets traced by POV-Ray's SDL trace() and compared ray by ray with our double-precision
// oracle (docs/verification.md, "Hit sets"). POV-Ray reads the rays with #read and writes
// each hit with 17 decimals; the geometry is a union of double-precision triangle objects
// holding our float32 vertices exactly, plus spheres, so both sides intersect the same shapes
// in double and should agree to ~1e-13.
#pragma once

#include "framework/oracle/oracle.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

// trace() reports the nearest hit at distance >= 1e-4 along the normalised direction
// (POV-Ray's MIN_ISECT_DEPTH); the oracle is asked with the same lower bound.
inline constexpr double kPovTraceMinDistance = 1e-4;

// Rays whose nearest hit lies within this barycentric distance of a triangle edge (or that
// pass that close outside an edge before their hit) are not compared: on an edge either
// answer is right (OracleHit::edgeMargin).
inline constexpr double kHitSetEdgeMargin = 1e-6;

// Hit points must agree within this fraction of the scene's size (its bounding-box diagonal,
// at least 1): the float32 bound of mesh2 hits
// (docs/verification.md#5-hit-sets-rtlab-refs---hits); double triangles do far better.
inline constexpr double kHitSetPointTolerance = 1e-6;

struct PovTraceHit {
    bool hit = false;
    DVec3 point{0.0};
    DVec3 normal{0.0};  // as POV-Ray stores it: triangles -(CCW normal), spheres outward
};

// A reproducible ray set: a third camera rays through random image positions, a third aimed
// from random points around the scene at random points on random primitives, a third random
// origins and directions. Directions are unit; tMin = kPovTraceMinDistance.
std::vector<OracleRay> makeHitSetRays(const Scene& scene, const Camera& camera, size_t count, uint64_t seed);

// Runs povray once (in a temporary folder) to trace every ray against the scene's geometry.
// Throws rtlab::Error with one line (and keeps the log) when POV-Ray fails.
std::vector<PovTraceHit> traceWithPovray(const Scene& scene, const std::vector<OracleRay>& rays);

struct HitSetComparison {
    size_t rays = 0;
    size_t nearEdge = 0;            // not compared
    size_t compared = 0;
    size_t hitMissAgreements = 0;   // among the compared rays
    size_t bothHit = 0;
    double pointTolerance = 0.0;    // absolute
    double maxPointError = 0.0;     // over rays where both hit
    double medianPointError = 0.0;
    size_t pointsOverTolerance = 0;
    double maxNormalError = 0.0;    // 1 - |cos| between POV-Ray's and the oracle's normal
    std::vector<std::string> mismatches;  // the first few, one line each

    bool agrees() const { return hitMissAgreements == compared && pointsOverTolerance == 0; }
};

HitSetComparison compareWithOracle(const Scene& scene, const std::vector<OracleRay>& rays,
                                   const std::vector<PovTraceHit>& povHits);

}  // namespace rtlab
