// The tasks a worker can run and the plain inputs and outputs they exchange with the grader
// (worker_protocol.h). Inputs carry only what the student's functions are called with, never
// what the grader expects back.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"
#include "framework/interface/bvh.h"

#include <cstdint>
#include <type_traits>

namespace rtlab::grader::worker {

// Task names (worker_tasks.cpp has the one table that maps them to code).
inline constexpr const char* kTaskNone = "none";
inline constexpr const char* kTaskBox = "box";                  // [BoxQuery] -> per query u8 hit, f32 tEnter
inline constexpr const char* kTaskTriangle = "triangle";        // [TriangleQuery] -> per query u8 hit, f32 t
inline constexpr const char* kTaskClosestTriangle = "closest-triangle";  // [triangle], [Ray] -> per ray f32 nearest t
inline constexpr const char* kTaskSphere = "sphere";            // [SphereQuery] -> per query u8 hit, f32 t
inline constexpr const char* kTaskSplit = "split";              // SplitCall... -> per call u32 k, u32 order[n]
inline constexpr const char* kTaskBvhBuild = "bvh-build";       // scene, BvhOptions -> [BvhNode], [u32]
inline constexpr const char* kTaskBvhQuery = "bvh-query";       // u8 BvhQuery, [Ray] -> [RawQuery]
inline constexpr const char* kTaskRender = "render";            // scene, RenderRequest -> w, h, c, [f32]

struct BoxQuery {
    Bounds3f box;
    Ray ray;  // tMin and tMax of the query
};

struct TriangleQuery {
    Ray ray;  // tMax of the query is ray.tMax
    Vec3 p0, p1, p2;
};

struct SphereQuery {
    Ray ray;
    Vec3 centre;
    float radius;
};

enum class SplitFunction : uint8_t { Median, Middle, EqualCounts, SahSweep, SahBuckets };

// One call of a split function: followed on the wire by the boxes of its primitives.
struct SplitCall {
    SplitFunction function;
    BvhOptions options;
};

enum class BvhQuery : uint8_t { Ordered, Recursive, Occluded };

// What a traversal returned for one ray, and the work the framework's counters saw (feedback
// only: the counters live in the worker, so student code could change them).
struct RawQuery {
    uint32_t prim;  // kNoHit on a miss; occluded queries: 1 or 0
    float t;
    uint32_t nodeVisits;
    uint32_t primitiveTests;
};

struct RenderRequest {
    uint32_t camera;  // index into the scene's cameras
    int32_t width, height;
    int32_t threads;
};

static_assert(std::is_trivially_copyable_v<BoxQuery> && std::is_trivially_copyable_v<TriangleQuery> &&
              std::is_trivially_copyable_v<SphereQuery> && std::is_trivially_copyable_v<SplitCall> &&
              std::is_trivially_copyable_v<RawQuery> && std::is_trivially_copyable_v<RenderRequest>);

}  // namespace rtlab::grader::worker
