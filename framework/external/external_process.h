// Running an external renderer (POV-Ray, Blender) headless: in a working folder, stdin from
// /dev/null, stdout and stderr into a log file (so nothing it prints can block it), and a hard
// wall-clock limit after which it is killed. It stays in our process group, so Ctrl-C stops it
// with us.
#pragma once

#include "framework/external/temporary_directory.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rtlab {

struct ExternalRun {
    int exitStatus = -1;    // its exit status, or 128 + the signal that ended it
    bool timedOut = false;  // killed when the time limit passed
    double seconds = 0.0;   // wall time

    bool succeeded() const { return !timedOut && exitStatus == 0; }
};

// Runs `program arguments...` (found on PATH unless it contains a '/') in workDir with its
// output in logPath, and waits at most timeLimitSeconds. Throws rtlab::Error with one line when
// the program cannot be started: "cannot start PROGRAM: REASON (HINT)", e.g. the hint
// "install it with scripts/install-deps".
ExternalRun runExternal(const std::string& program, const std::vector<std::string>& arguments,
                        const std::filesystem::path& workDir, const std::filesystem::path& logPath,
                        double timeLimitSeconds, const std::string& hint);

// The program's log, where it said what went wrong: one line of it, or "".
using ErrorLineFinder = std::function<std::string(const std::filesystem::path& log)>;

// runExternal in `work` with the log in work/<logName>. When the program exits non-zero or
// overruns the limit, keeps the folder and throws rtlab::Error with one line: "PROGRAM failed
// (exit N) WHAT: LINE; log: PATH" (LINE from errorLine) or "PROGRAM took longer than S s WHAT
// (killed); log: PATH".
void runExternalOrThrow(const std::string& program, const std::vector<std::string>& arguments, TemporaryDirectory& work,
                        const std::string& logName, double timeLimitSeconds, const std::string& hint,
                        const std::string& what, const ErrorLineFinder& errorLine);

// What `program --version` says of itself: the first line it prints that starts with `name`
// and a space. Throws rtlab::Error with one line when it cannot be started or prints no such
// line.
std::string externalVersion(const std::string& program, const std::string& name, double timeLimitSeconds,
                            const std::string& hint);

// A time limit as people write it: 600, 0.5.
std::string secondsText(double seconds);

}  // namespace rtlab
