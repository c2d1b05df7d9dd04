// a3's tasks (grid_tasks.cpp) and their inputs.
#pragma once

#include "framework/interface/grid.h"
#include "grader/wire/task_inputs.h"

#include <array>

namespace rtlab::grader::worker {

inline constexpr const char* kTaskGridResolution = "grid-resolution";  // [ResolutionCall] -> per call i32[3]
inline constexpr const char* kTaskGridCell = "grid-cell";    // GridFrame, [Vec3] -> per point i32[3]
inline constexpr const char* kTaskGridRange = "grid-range";  // GridFrame, [Bounds3f] -> per box i32[6]
inline constexpr const char* kTaskDdaSetup = "dda-setup";    // GridFrame, [DdaSetupCall] -> [DdaState]
inline constexpr const char* kTaskDdaStep = "dda-step";      // [DdaStepCall] -> per call u8, DdaState
inline constexpr const char* kTaskDdaWalk = "dda-walk";      // GridFrame, [DdaSetupCall] -> per walk u32 n, i32[3] x n
inline constexpr const char* kTaskGridBuild = "grid-build";  // scene, GridOptions -> GridFrame, [u32], [u32]
inline constexpr const char* kTaskGridQuery = "grid-query";  // u8 QueryKind, [Ray] -> [RawQuery]
inline constexpr const char* kTaskGridGivenQuery = "grid-given-query";  // grid (grid_codec.h), u8 QueryKind, [Ray] -> [RawQuery]

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

// The longest walk dda-walk reports: more cells than any graded grid has along a ray.
inline constexpr uint32_t kMaxWalkCells = 4096;

static_assert(std::is_trivially_copyable_v<GridFrame> && std::is_trivially_copyable_v<ResolutionCall> &&
              std::is_trivially_copyable_v<DdaSetupCall> && std::is_trivially_copyable_v<DdaStepCall>);

}  // namespace rtlab::grader::worker
