#include "grader/worker/worker_tasks.h"

#include "grader/wire/task_inputs.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace rtlab::grader::worker {
namespace {

void runNothing(ByteReader&, ByteWriter&, WorkerState&) {}

// Function-local, so registrations from other files' static initialisers find it built in
// whatever order the linker puts those files.
std::vector<NamedTask>& tasks() {
    static std::vector<NamedTask> list{{kTaskNone, runNothing}};
    return list;
}

}  // namespace

TaskRegistration::TaskRegistration(std::initializer_list<NamedTask> added) {
    for (const NamedTask& task : added) {
        if (findTask(task.name)) {
            std::fprintf(stderr, "rtlab-worker: task %.*s registered twice\n", int(task.name.size()), task.name.data());
            std::abort();
        }
        tasks().push_back(task);
    }
}

Task findTask(std::string_view name) {
    for (const NamedTask& task : tasks())
        if (task.name == name) return task.run;
    return nullptr;
}

}  // namespace rtlab::grader::worker
