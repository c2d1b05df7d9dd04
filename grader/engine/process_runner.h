// The grader's children that talk back only through their output: the compiler (inside its
// sandbox) and git, run by framework/core/child_process.h in a process group of their own, with
// the output captured up to a cap, resource limits and no core dumps; the worker has its own,
// richer conversation (sandbox.h).
#pragma once

#include <string>
#include <vector>

namespace rtlab::grader {

struct ProcessLimits {
    double wallSeconds = 60.0;
    int cpuSeconds = 120;
    int memoryMiB = 4096;         // address space of each process it starts
    size_t outputBytes = 16384;  // stdout and stderr together; the rest is counted, not kept
    bool asNobody = false;       // drop to the unprivileged user nobody first (when root)
};

struct ProcessResult {
    int exitCode = -1;       // -1 when it did not exit by itself
    bool timedOut = false;
    int signal = 0;
    std::string output;      // raw bytes: escape before showing
    size_t droppedBytes = 0;
    std::string failure;     // why it could not be run, or how it ended, in a few words; empty on exit 0

    bool succeeded() const { return exitCode == 0 && !timedOut; }
};

// argv[0] is the program's absolute path; the environment is exactly `environment`.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::vector<std::string>& environment, const ProcessLimits& limits);

}  // namespace rtlab::grader
