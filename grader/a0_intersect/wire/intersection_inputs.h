// a0's tasks (intersection_tasks.cpp) and their inputs.
#pragma once

#include "grader/wire/task_inputs.h"

namespace rtlab::grader::worker {

inline constexpr const char* kTaskBox = "box";            // [BoxQuery] -> per query u8 hit, f32 tEnter
// [Bounds3f] boxes, [Ray] rays -> per ray, per box: u8 hit, f32 tEnter. The calls of kTaskBox on
// every (ray, box) pair, ray by ray, in a sixth of the bytes when the boxes are few.
inline constexpr const char* kTaskRaysAgainstBoxes = "rays-against-boxes";
inline constexpr const char* kTaskTriangle = "triangle";  // [TriangleQuery] -> per query u8 hit, f32 t
inline constexpr const char* kTaskClosestTriangle = "closest-triangle";  // [triangle], [Ray] -> per ray f32 nearest t
inline constexpr const char* kTaskSphere = "sphere";      // [SphereQuery] -> per query u8 hit, f32 t

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

static_assert(std::is_trivially_copyable_v<BoxQuery> && std::is_trivially_copyable_v<TriangleQuery> &&
              std::is_trivially_copyable_v<SphereQuery>);

}  // namespace rtlab::grader::worker
