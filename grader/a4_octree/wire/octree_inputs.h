// a4's tasks (octree_tasks.cpp) and their inputs.
#pragma once

#include "framework/interface/octree.h"
#include "grader/wire/task_inputs.h"

namespace rtlab::grader::worker {

inline constexpr const char* kTaskOctreeRootBox = "octree-root-box";      // [Bounds3f] -> [Bounds3f]
inline constexpr const char* kTaskOctreeChildBox = "octree-child-box";    // [ChildBoxCall] -> [Bounds3f]
inline constexpr const char* kTaskOctreeChildIndex = "octree-child-index";  // [ChildIndexCall] -> per call i32
inline constexpr const char* kTaskTriangleBox = "triangle-box";           // [TriangleBoxCall] -> per call u8
inline constexpr const char* kTaskOctreeMirror = "octree-mirror";         // Bounds3f root, [Ray] -> [MirroredRay]
inline constexpr const char* kTaskOctreeRootSpan = "octree-root-span";    // Bounds3f root, [Ray] -> [NodeSpan]
inline constexpr const char* kTaskOctreeMid = "octree-mid";               // [MidCall] -> [Vec3]
inline constexpr const char* kTaskOctreeFirstNode = "octree-first-node";  // [FirstNodeCall] -> per call i32
inline constexpr const char* kTaskOctreeNextNode = "octree-next-node";    // [NextNodeCall] -> per call i32
inline constexpr const char* kTaskOctreeBuild = "octree-build";  // scene, OctreeOptions -> Bounds3f root, [OctreeNode], [u32]
inline constexpr const char* kTaskOctreeQuery = "octree-query";  // u8 QueryKind, [Ray] -> [RawQuery]
inline constexpr const char* kTaskOctreeGivenQuery = "octree-given-query";  // octree (octree_codec.h), u8 QueryKind, [Ray] -> [RawQuery]
// The closest-hit traversal again, listing the leaves it enters (Traversal::enterLeaf), in order.
inline constexpr const char* kTaskOctreeLeaves = "octree-leaves";  // [Ray] -> per ray u32 n, u32 node[n]

struct ChildBoxCall {
    Bounds3f box;
    int32_t child;
};

struct ChildIndexCall {
    Vec3 p;
    Vec3 mid;
};

struct TriangleBoxCall {
    Vec3 p0, p1, p2;
    Bounds3f box;
};

struct MidCall {
    Ray mirrored;
    NodeSpan span;
    Bounds3f box;
};

struct FirstNodeCall {
    Vec3 t0;
    Vec3 tm;
};

struct NextNodeCall {
    int32_t current;
    Vec3 t1;
};

// The most leaves octree-leaves lists for one ray: more than any walk through a graded octree
// enters (the rest are cut, and a longer list is wrong anyway).
inline constexpr uint32_t kMaxListedLeaves = 4096;

static_assert(std::is_trivially_copyable_v<ChildBoxCall> && std::is_trivially_copyable_v<ChildIndexCall> &&
              std::is_trivially_copyable_v<TriangleBoxCall> && std::is_trivially_copyable_v<MidCall> &&
              std::is_trivially_copyable_v<FirstNodeCall> && std::is_trivially_copyable_v<NextNodeCall> &&
              std::is_trivially_copyable_v<OctreeNode> && std::is_trivially_copyable_v<OctreeOptions> &&
              std::is_trivially_copyable_v<MirroredRay> && std::is_trivially_copyable_v<NodeSpan>);

}  // namespace rtlab::grader::worker
