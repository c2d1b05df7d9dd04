// The shadow rays of the race against Embree (docs/performance.md#ray-sets): one any-hit query
// per primary ray that hits, from where it hits towards a point light.
#pragma once

#include "bench/bench_system.h"
#include "framework/core/bounds.h"

#include <span>
#include <vector>

namespace rtlab::bench {

// For every primary ray with a hit (hits[i].prim != kNoHit): the point it hits, moved back
// towards the ray's origin by 1e-4 of the hit distance so that the surface does not block its
// own shadow ray, to a point light at centre + 2R * normalize(-0.6, 1, 0.4) (R: half the
// bounds' diagonal; above the scene and on the other side from the primary rays' eye), with a
// unit direction and tMax the distance to the light.
std::vector<BenchSegment> makeShadowRays(std::span<const BenchRay> primary, std::span<const TraceResult> hits,
                                         const Bounds3f& bounds);

}  // namespace rtlab::bench
