// Running an external renderer (POV-Ray, Blender) headless: in a working folder, stdin from
// /dev/null, stdout and stderr into a log file (so nothing it prints can block it), and a hard
// wall-clock limit after which it is killed. It stays in our process group, so Ctrl-C stops it
// with us.
#pragma once

#include <filesystem>
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

// A time limit as people write it: 600, 0.5.
std::string secondsText(double seconds);

}  // namespace rtlab
