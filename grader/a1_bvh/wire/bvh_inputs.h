// a1's and a2's tasks (bvh_tasks.cpp) and their inputs.
#pragma once

#include "framework/interface/bvh.h"
#include "grader/wire/task_inputs.h"

namespace rtlab::grader::worker {

inline constexpr const char* kTaskSplit = "split";           // SplitCall... -> per call u32 k, u32 order[n]
inline constexpr const char* kTaskBvhBuild = "bvh-build";    // scene, BvhOptions -> [BvhNode], [u32]
inline constexpr const char* kTaskBvhQuery = "bvh-query";    // u8 QueryKind, [Ray] -> [RawQuery]
inline constexpr const char* kTaskBvhGivenQuery = "bvh-given-query";  // BVH (bvh_codec.h), u8 QueryKind, [Ray] -> [RawQuery]
inline constexpr const char* kTaskBvhVisits = "bvh-visits";  // [Ray] -> per ray u32 n, u32 prim[n]

enum class SplitFunction : uint8_t { Median, Middle, EqualCounts, SahSweep, SahBuckets };

// One call of a split function: followed on the wire by the boxes of its primitives.
struct SplitCall {
    SplitFunction function;
    BvhOptions options;
};

static_assert(std::is_trivially_copyable_v<SplitCall>);

}  // namespace rtlab::grader::worker
