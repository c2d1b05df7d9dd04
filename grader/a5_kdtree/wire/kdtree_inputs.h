// a5's tasks (kdtree_tasks.cpp) and their inputs.
#pragma once

#include "framework/interface/bsp.h"
#include "framework/interface/kdtree.h"
#include "grader/wire/task_inputs.h"

namespace rtlab::grader::worker {

inline constexpr const char* kTaskKdSahCost = "kd-sah-cost";          // [KdSahCall] -> per call f64
inline constexpr const char* kTaskKdEventOrder = "kd-event-order";    // [KdEventPair] -> per pair u8
inline constexpr const char* kTaskKdSortedEvents = "kd-sorted-events";  // u64 n, n x ([Bounds3f], [u32], i32 axis) -> per case [KdEvent]
inline constexpr const char* kTaskKdBestSplit = "kd-best-split";      // u64 n, n x (KdSplitCall, 3 x [KdEvent]) -> per case KdSplit
inline constexpr const char* kTaskKdClassify = "kd-classify";         // [KdClassifyCall] -> per call u8 KdSide
inline constexpr const char* kTaskKdMaxDepth = "kd-max-depth";        // [u64] -> per call i32
inline constexpr const char* kTaskKdDecide = "kd-decide";             // [KdDecideCall] -> [KdNodeDecision]
inline constexpr const char* kTaskKdChildOrder = "kd-child-order";    // [KdChildOrderCall] -> [KdChildOrder]
inline constexpr const char* kTaskKdWalk = "kd-walk";                 // scene, KdTreeFrame, [KdNode], [u32], u8 QueryKind, [Ray] -> per ray RawQuery, u32 n, u32 prim[n]
inline constexpr const char* kTaskKdBuild = "kd-build";               // scene, KdTreeOptions, u8 KdBuildFunction -> KdTreeFrame, [KdNode], [u32]
inline constexpr const char* kTaskKdQuery = "kd-query";               // u8 QueryKind, [Ray] -> [RawQuery]
inline constexpr const char* kTaskKdGivenQuery = "kd-given-query";    // KD-tree (kdtree_codec.h), u8 QueryKind, [Ray] -> [RawQuery]
inline constexpr const char* kTaskBspBuild = "bsp-build";             // scene, BspOptions -> u64 nodes
inline constexpr const char* kTaskBspQuery = "bsp-query";             // u8 QueryKind, [Ray] -> [RawQuery]

struct KdSahCall {
    Bounds3f node;
    int32_t axis;
    float position;
    uint32_t nBelow, nAbove;
    KdCosts costs;
};

struct KdEventPair {
    KdEvent a, b;
};

// kdBestSplit's scalar arguments; the three event lists follow on the wire.
struct KdSplitCall {
    Bounds3f node;
    uint32_t primCount;
    KdCosts costs;
};

struct KdClassifyCall {
    Bounds3f box;
    int32_t axis;
    float position;
    KdSide planarSide;
};

struct KdDecideCall {
    uint32_t primCount;
    int32_t depth;
    KdSplit best;
    int32_t badRefines;
    KdTreeOptions options;
};

struct KdChildOrderCall {
    int32_t axis;
    float split;
    Ray ray;
    float tMin, tMax;
};

// A KD-tree without its arrays (KdTree holds vectors).
struct KdTreeFrame {
    Bounds3f bounds;
    int32_t maxDepth;
};

enum class KdBuildFunction : uint8_t { Sort, NlogN };

static_assert(std::is_trivially_copyable_v<KdSahCall> && std::is_trivially_copyable_v<KdEventPair> &&
              std::is_trivially_copyable_v<KdSplitCall> && std::is_trivially_copyable_v<KdClassifyCall> &&
              std::is_trivially_copyable_v<KdDecideCall> && std::is_trivially_copyable_v<KdChildOrderCall> &&
              std::is_trivially_copyable_v<KdTreeFrame> && std::is_trivially_copyable_v<KdSplit> &&
              std::is_trivially_copyable_v<KdNodeDecision> && std::is_trivially_copyable_v<KdChildOrder> &&
              std::is_trivially_copyable_v<KdNode> && std::is_trivially_copyable_v<KdEvent> &&
              std::is_trivially_copyable_v<BspOptions>);

}  // namespace rtlab::grader::worker
