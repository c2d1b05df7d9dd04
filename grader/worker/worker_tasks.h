// The tasks a worker runs. Each family of tasks (intersection_tasks.cpp, bvh_tasks.cpp,
// grid_tasks.cpp, ...) names them in its own inputs header and registers them with one
// TaskRegistration, so a new assignment's tasks are a file of their own and no list here
// changes. A task reads its input, calls student code and writes raw results; what one phase
// builds (a scene, a structure) stays in WorkerState for the phases after it.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/scene/scene.h"
#include "grader/wire/wire_format.h"

#include <any>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string_view>

namespace rtlab::grader::worker {

struct WorkerState {
    Scene scene;
    std::unique_ptr<PrimitiveSet> primitives;
    // What the last build phase made (a Bvh, a UniformGrid, ...): its query phases read it
    // back with builtStructure<T>().
    std::any structure;
};

// The structure a build phase left (build tasks emplace an empty one before calling the
// student's build, so a build that threw leaves it empty), or a WireError when no build phase
// came first.
template <typename T>
const T& builtStructure(const WorkerState& state) {
    const T* built = std::any_cast<T>(&state.structure);
    if (!built || !state.primitives) throw WireError("a query before the build");
    return *built;
}

// The primitives of the last build phase's scene, for tasks that bring their own structure.
inline const PrimitiveSet& builtPrimitives(const WorkerState& state) {
    if (!state.primitives) throw WireError("a query before the build");
    return *state.primitives;
}

// Thrown by a task that will not call student code on what an earlier phase made, because it
// breaks a rule that code may rely on (a BVH whose child indices point back up would send a
// correct traversal round a cycle): the phase fails as "not run" with this reason, which names
// the earlier phase's result, not the stub the task would have called.
struct PhaseNotRun : std::runtime_error {
    using std::runtime_error::runtime_error;
};

using Task = void (*)(ByteReader& input, ByteWriter& output, WorkerState& state);

struct NamedTask {
    std::string_view name;
    Task run;
};

// `const TaskRegistration registration{{kTaskX, runX}, ...};` at namespace scope of a tasks
// file adds its tasks while the worker starts; a name registered twice aborts the worker.
struct TaskRegistration {
    TaskRegistration(std::initializer_list<NamedTask> tasks);
};

// nullptr for a name no task has.
Task findTask(std::string_view name);

}  // namespace rtlab::grader::worker
