// The tasks a worker can run and the plain inputs and outputs they exchange with the grader
// (worker_protocol.h). Inputs carry only what the student's functions are called with, never
// what the grader expects back.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"
#include "framework/interface/bvh.h"
#include "framework/interface/grid.h"

#include <array>
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
inline constexpr const char* kTaskBvhVisits = "bvh-visits";     // [Ray] -> per ray u32 n, u32 prim[n]
inline constexpr const char* kTaskRender = "render";            // scene, RenderRequest -> w, h, c, [f32]
inline constexpr const char* kTaskGridResolution = "grid-resolution";  // [ResolutionCall] -> per call i32[3]
inline constexpr const char* kTaskGridCell = "grid-cell";       // GridFrame, [Vec3] -> per point i32[3]
inline constexpr const char* kTaskGridRange = "grid-range";     // GridFrame, [Bounds3f] -> per box i32[6]
inline constexpr const char* kTaskDdaSetup = "dda-setup";       // GridFrame, [DdaSetupCall] -> [DdaState]
inline constexpr const char* kTaskDdaStep = "dda-step";         // [DdaStepCall] -> per call u8, DdaState
inline constexpr const char* kTaskDdaWalk = "dda-walk";         // GridFrame, [DdaSetupCall] -> per walk u32 n, i32[3] x n
inline constexpr const char* kTaskGridBuild = "grid-build";     // scene, GridOptions -> GridFrame, [u32], [u32]
inline constexpr const char* kTaskGridQuery = "grid-query";     // u8 GridQuery, [Ray] -> [RawQuery]

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

// The frame of a uniform grid without its cells (UniformGrid holds vectors).
struct GridFrame {
    Bounds3f bounds;
    std::array<int32_t, 3> resolution;
    Vec3 cellWidth;
    Vec3 inverseWidth;
};

struct ResolutionCall {
    Bounds3f bounds;
    uint64_t primCount;
    GridOptions options;
};

struct DdaSetupCall {
    Ray ray;
    float tEnter, tExit;
};

struct DdaStepCall {
    DdaState state;
    std::array<int32_t, 3> resolution;
};

// The most primitive tests bvh-visits lists for one ray (the rest are cut: the list is judged
// by its start and by where leaves are entered, and a longer one is already wrong).
inline constexpr uint32_t kMaxListedTests = 4096;

// The longest walk dda-walk reports: more cells than any graded grid has along a ray.
inline constexpr uint32_t kMaxWalkCells = 4096;

enum class GridQuery : uint8_t { Closest, Occluded };

struct RenderRequest {
    uint32_t camera;  // index into the scene's cameras
    int32_t width, height;
    int32_t threads;
    char accelerator[40];  // a registry name (accelerator_registry.h), NUL-terminated
};

static_assert(std::is_trivially_copyable_v<BoxQuery> && std::is_trivially_copyable_v<TriangleQuery> &&
              std::is_trivially_copyable_v<SphereQuery> && std::is_trivially_copyable_v<SplitCall> &&
              std::is_trivially_copyable_v<RawQuery> && std::is_trivially_copyable_v<RenderRequest> &&
              std::is_trivially_copyable_v<GridFrame> && std::is_trivially_copyable_v<ResolutionCall> &&
              std::is_trivially_copyable_v<DdaSetupCall> && std::is_trivially_copyable_v<DdaStepCall>);

}  // namespace rtlab::grader::worker
