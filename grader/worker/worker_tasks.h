// The tasks a worker runs (task_inputs.h names them and their inputs). Each reads its input,
// calls student code and writes raw results; what one phase builds (a scene, a BVH) stays in
// WorkerState for the phases after it.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/bvh.h"
#include "framework/interface/grid.h"
#include "framework/scene/scene.h"
#include "grader/wire_format.h"

#include <memory>
#include <string_view>

namespace rtlab::grader::worker {

struct WorkerState {
    Scene scene;
    std::unique_ptr<PrimitiveSet> primitives;
    Bvh bvh;
    UniformGrid grid;
};

using Task = void (*)(ByteReader& input, ByteWriter& output, WorkerState& state);

// nullptr for a name no task has.
Task findTask(std::string_view name);

// intersection_tasks.cpp
void runBoxQueries(ByteReader& input, ByteWriter& output, WorkerState& state);
void runTriangleQueries(ByteReader& input, ByteWriter& output, WorkerState& state);
void runClosestTriangle(ByteReader& input, ByteWriter& output, WorkerState& state);
void runSphereQueries(ByteReader& input, ByteWriter& output, WorkerState& state);
// bvh_tasks.cpp
void runSplitCalls(ByteReader& input, ByteWriter& output, WorkerState& state);
void runBvhBuild(ByteReader& input, ByteWriter& output, WorkerState& state);
void runBvhQuery(ByteReader& input, ByteWriter& output, WorkerState& state);
void runBvhVisits(ByteReader& input, ByteWriter& output, WorkerState& state);
// grid_tasks.cpp
void runGridResolution(ByteReader& input, ByteWriter& output, WorkerState& state);
void runGridCell(ByteReader& input, ByteWriter& output, WorkerState& state);
void runGridRange(ByteReader& input, ByteWriter& output, WorkerState& state);
void runDdaSetup(ByteReader& input, ByteWriter& output, WorkerState& state);
void runDdaStep(ByteReader& input, ByteWriter& output, WorkerState& state);
void runDdaWalk(ByteReader& input, ByteWriter& output, WorkerState& state);
void runGridBuild(ByteReader& input, ByteWriter& output, WorkerState& state);
void runGridQuery(ByteReader& input, ByteWriter& output, WorkerState& state);
// render_task.cpp
void runRender(ByteReader& input, ByteWriter& output, WorkerState& state);

}  // namespace rtlab::grader::worker
