#include "grader/worker/worker_tasks.h"

#include "grader/worker/task_inputs.h"

#include <array>

namespace rtlab::grader::worker {
namespace {

void runNothing(ByteReader&, ByteWriter&, WorkerState&) {}

struct NamedTask {
    std::string_view name;
    Task run;
};

constexpr std::array kTasks = {
    NamedTask{kTaskNone, runNothing},
    NamedTask{kTaskBox, runBoxQueries},
    NamedTask{kTaskTriangle, runTriangleQueries},
    NamedTask{kTaskClosestTriangle, runClosestTriangle},
    NamedTask{kTaskSphere, runSphereQueries},
    NamedTask{kTaskSplit, runSplitCalls},
    NamedTask{kTaskBvhBuild, runBvhBuild},
    NamedTask{kTaskBvhQuery, runBvhQuery},
    NamedTask{kTaskBvhVisits, runBvhVisits},
    NamedTask{kTaskRender, runRender},
    NamedTask{kTaskGridResolution, runGridResolution},
    NamedTask{kTaskGridCell, runGridCell},
    NamedTask{kTaskGridRange, runGridRange},
    NamedTask{kTaskDdaSetup, runDdaSetup},
    NamedTask{kTaskDdaStep, runDdaStep},
    NamedTask{kTaskDdaWalk, runDdaWalk},
    NamedTask{kTaskGridBuild, runGridBuild},
    NamedTask{kTaskGridQuery, runGridQuery},
};

}  // namespace

Task findTask(std::string_view name) {
    for (const NamedTask& task : kTasks)
        if (task.name == name) return task.run;
    return nullptr;
}

}  // namespace rtlab::grader::worker
