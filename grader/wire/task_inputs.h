// What every worker task shares with the grader (worker_protocol.h carries it): the raw answer
// of a traversal query, the query kinds a structure's query task answers, and the render task.
// Each family of tasks names its tasks and plain inputs in a header of its own
// (intersection_inputs.h, bvh_inputs.h, grid_inputs.h, ...). Inputs carry only what the
// student's functions are called with, never what the grader expects back.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"

#include <cstdint>
#include <type_traits>

namespace rtlab::grader::worker {

inline constexpr const char* kTaskNone = "none";
inline constexpr const char* kTaskRender = "render";  // scene, RenderRequest -> w, h, c, [f32]
// The report's viewer pages: the student's walk of a failing case's rays, through the structure
// the student's code builds under a registry name. Scene, TraceRequest, [Ray], [u8 any-hit] ->
// per ray the bytes of a TraversalTrace (traversal_trace_format.h), which the grader decodes as
// untrusted data.
inline constexpr const char* kTaskTraceRays = "trace-rays";
// The most operations a trace keeps (the rest are counted, not kept), and so the most bytes one
// may take: the grader reads no more.
inline constexpr uint32_t kMaxTraceOps = 1u << 16;
inline constexpr uint64_t kMaxTraceBytes = 24 + 40 * uint64_t(kMaxTraceOps);

// What a structure's query task answers for each ray of a phase.
enum class QueryKind : uint8_t {
    Closest,    // the closest-hit traversal
    Occluded,   // the any-hit traversal (ray.tMax bounds the segment)
    Recursive,  // a second closest-hit traversal, where an assignment has one (a1's recursive walk)
};

// What a traversal returned for one ray, and the work the framework's counters saw (feedback
// only: the counters live in the worker, so student code could change them).
struct RawQuery {
    uint32_t prim;  // kNoHit on a miss; occluded queries: 1 or 0
    float t;
    uint32_t nodeVisits;
    uint32_t primitiveTests;
};

// The most primitive tests a visits task lists for one ray (the rest are cut: the list is
// judged by its start and by where leaves are entered, and a longer one is already wrong).
inline constexpr uint32_t kMaxListedTests = 4096;

struct RenderRequest {
    uint32_t camera;  // index into the scene's cameras
    int32_t width, height;
    int32_t threads;
    char accelerator[40];  // a registry name (accelerator_registry.h), NUL-terminated
};

struct TraceRequest {
    char accelerator[40];  // a registry name (accelerator_registry.h), NUL-terminated
};

static_assert(std::is_trivially_copyable_v<RawQuery> && std::is_trivially_copyable_v<RenderRequest> &&
              std::is_trivially_copyable_v<TraceRequest>);

}  // namespace rtlab::grader::worker
