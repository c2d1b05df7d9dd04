// Running another program and waiting for it: an external renderer, the compiler in its
// sandbox, git, a batch's grading children. (The sandboxed worker, which holds a conversation
// over pipes while it runs, has its own start: grader/engine/sandbox_start.h.) The child's
// stdin is /dev/null; its output is captured up to a cap or written to a log file, so nothing it
// prints can block it or keep the wait alive; a hard wall-clock limit, which nothing the child
// does can extend, ends it. What differs between callers is an option.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtlab {

struct ChildOptions {
    // argv[0] is the program: a path, or with searchPath a name looked up on PATH.
    std::vector<std::string> argv;
    bool searchPath = false;
    // Exactly this environment; none given: ours.
    std::optional<std::vector<std::string>> environment;
    std::filesystem::path workDir;  // empty: ours

    // Where its stdout and stderr go: into ChildRun::output (at most captureBytes kept, the rest
    // counted), or with a logPath into that file (truncated, or appended to with appendLog).
    size_t captureBytes = 16384;
    std::filesystem::path logPath;
    bool appendLog = false;

    double wallSeconds = 60.0;
    // In a process group of its own, killed as a whole when it ends or overruns. Without it the
    // child stays in ours, so Ctrl-C stops it with us.
    bool ownGroup = true;
    // With ownGroup, on overrun also kill what it started outside its group (a sandbox's own
    // session), found through /proc and stopped before it is killed so it cannot start more.
    bool killDescendants = false;

    // Resource limits set in the child before it executes (0: not set), and the drop to the
    // unprivileged user nobody when we run as root.
    int cpuSeconds = 0;
    int memoryMiB = 0;  // address space
    bool noCoreDumps = false;
    bool asNobody = false;
};

struct ChildRun {
    bool started = false;   // false: it could not be executed (startError says why)
    std::string startError; // e.g. "No such file or directory"
    bool timedOut = false;  // the wall-clock limit ended it
    int exitCode = -1;      // when it exited by itself
    int signal = 0;         // when a signal ended it
    double seconds = 0.0;   // wall time
    std::string output;     // raw bytes, when captured: escape before showing
    size_t droppedBytes = 0;

    bool succeeded() const { return started && !timedOut && signal == 0 && exitCode == 0; }
};

ChildRun runChild(const ChildOptions& options);

}  // namespace rtlab
