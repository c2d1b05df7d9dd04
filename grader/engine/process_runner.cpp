#include "grader/engine/process_runner.h"

#include "framework/core/child_process.h"

#include <cstring>

namespace rtlab::grader {

ProcessResult runProcess(const std::vector<std::string>& argv, const std::vector<std::string>& environment, const ProcessLimits& limits) {
    ChildOptions options;
    options.argv = argv;
    options.environment = environment;
    options.captureBytes = limits.outputBytes;
    options.wallSeconds = limits.wallSeconds;
    options.cpuSeconds = limits.cpuSeconds;
    options.memoryMiB = limits.memoryMiB;
    options.noCoreDumps = true;
    options.asNobody = limits.asNobody;
    ChildRun run = runChild(options);

    ProcessResult result;
    result.output = std::move(run.output);
    result.droppedBytes = run.droppedBytes;
    if (!run.started) {
        result.failure = "could not be started: " + run.startError;
    } else if (run.timedOut) {
        result.timedOut = true;
        result.failure = "stopped after the limit of " + std::to_string(int(limits.wallSeconds)) + " s";
    } else if (run.signal != 0) {
        result.signal = run.signal;
        result.failure = std::string("killed by signal ") + (sigabbrev_np(run.signal) ? sigabbrev_np(run.signal) : "?");
    } else {
        result.exitCode = run.exitCode;
        if (run.exitCode != 0) result.failure = "exit status " + std::to_string(run.exitCode);
    }
    return result;
}

}  // namespace rtlab::grader
