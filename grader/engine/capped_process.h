// A batch's grading child (this executable, grading one submission) under a hard wall-clock
// cap, by framework/core/child_process.h: in a process group of its own, its output appended to
// a log file, and on overrun its group and every process below it (a compiler, a worker, in
// whatever group or session they put themselves) killed.
#pragma once

#include <string>
#include <vector>

namespace rtlab::grader {

struct CappedRun {
    bool started = false;    // false: it could not be executed
    bool timedOut = false;   // the cap fired; the group was killed
    int exitCode = -1;       // when it exited
    int signal = 0;          // when a signal ended it
    double seconds = 0.0;

    bool succeeded() const { return started && !timedOut && signal == 0 && exitCode == 0; }
    // "exited with status 3", "killed by SIGSEGV", "took longer than 600 s (killed)"
    std::string describe(double capSeconds) const;
};

// Runs argv[0] with argv, stdin from /dev/null, stdout and stderr appended to logPath.
CappedRun runCapped(const std::vector<std::string>& argv, const std::string& logPath, double capSeconds);

// The last maxLines lines of a file, at most maxBytes read from its end.
std::string tailOfFile(const std::string& path, size_t maxLines, size_t maxBytes = 16384);

}  // namespace rtlab::grader
