// How a worker process starts: the grader spawns rtlab-sandbox-start (cli/sandbox_start_main.cpp)
// with the worker's pipes on descriptors 0-3, and that small program limits itself, drops to
// nobody and replaces itself with the worker, whose entry point loads the system-call filter
// before any other instruction (grader/worker/sandbox_entry.cpp). The grader does not fork
// itself: a fork copies its page tables (hundreds of MB of test inputs while grading) and makes
// every page it writes afterwards fault once, which cost more than the tests of a submission
// whose assignments are not started.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::grader {

struct SandboxStart {
    std::string worker;          // the worker executable
    uint64_t addressSpace = 0;   // bytes, RLIMIT_AS
    uint64_t cpuSeconds = 0;     // RLIMIT_CPU (soft; the hard limit is one more)
    pid_t grader = 0;            // the process that must still be the parent
};

// The path of rtlab-sandbox-start in this build.
std::string sandboxStartPath();

// argv for rtlab-sandbox-start (argv[0] included), and back. parseSandboxStart throws
// std::invalid_argument on anything but what sandboxStartArguments writes.
std::vector<std::string> sandboxStartArguments(const SandboxStart& start);
SandboxStart parseSandboxStart(int argc, const char* const* argv);

// In rtlab-sandbox-start: descriptors 0 (requests), 1 and 2 (output) and 3 (results) are set.
// Adds the filter as descriptor 4, closes every other, applies the limits, becomes nobody when
// root, and executes the worker. Never returns; exits with kExitSandboxFailed on any failure.
[[noreturn]] void startSandboxedWorker(const SandboxStart& start);

}  // namespace rtlab::grader
