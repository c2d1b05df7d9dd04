// A system under test: something that builds over a scene's triangles and answers closest-hit
// queries one ray at a time. rtlab's accelerators and Embree are the two kinds
// (docs/performance.md#embree-setup-and-mismatches).
#pragma once

#include "framework/interface/traversal_stats.h"
#include "framework/core/hit.h"
#include "framework/core/vec.h"

#include <optional>
#include <span>
#include <string>

namespace rtlab::bench {

// The shared ray array: origin and unit direction, 24 bytes. Every system builds its own ray
// struct from it inside the timed loop, as the reference harness did.
struct BenchRay {
    Vec3 origin;
    Vec3 direction;
};

// A shadow ray: blocked when anything lies at tMin = 0 < t <= tMax along it (an any-hit query).
struct BenchSegment {
    Vec3 origin;
    Vec3 direction;
    float tMax;
};

// What every query stores: the hit distance and primitive (kNoHit on a miss).
struct TraceResult {
    float t = kInfinity;
    uint32_t prim = kNoHit;
};

class BenchSystem {
public:
    virtual ~BenchSystem() = default;

    // "rtlab:bvh-buckets:12", "embree:medium", ...
    virtual std::string label() const = 0;
    // Builds afresh with up to `threads` threads (rtlab's builders take the CPUs the process may
    // use, so a 1T build runs pinned to one CPU). Only the build itself is timed, so the return
    // value is its wall time in ms.
    virtual double build(int threads) = 0;
    // Closest hits of rays; stats receives node visits and primitive tests where the system
    // counts them (rtlab does, Embree's release build does not).
    virtual void trace(std::span<const BenchRay> rays, TraceResult* results, TraversalStats& stats) const = 0;
    // Any-hit queries (1: blocked, 0: free), rtcOccluded1 on Embree's side.
    virtual void occluded(std::span<const BenchSegment> rays, uint8_t* blocked, TraversalStats& stats) const = 0;

    // Whether a build uses more than one thread when the process may use more than one CPU.
    virtual bool buildsInParallel() const = 0;
    virtual bool countsWork() const = 0;
    virtual std::optional<double> sahCost() const = 0;
    // Memory of the built structure (without the input triangles), divided by the triangles.
    virtual double bytesPerTriangle() const = 0;
    // Primitive references the built structure keeps per triangle (1 for a BVH, more where a
    // spatial partition lists a triangle in several cells or leaves); none where not known.
    virtual std::optional<double> referencesPerTriangle() const = 0;
};

}  // namespace rtlab::bench
