#include "framework/blender/blender_process.h"

#include "framework/external/external_process.h"

#include <cstdlib>
#include <fstream>

namespace rtlab {
namespace fs = std::filesystem;

namespace {

constexpr const char* kInstallHint = "install it with scripts/install-deps --blender, or set RTLAB_BLENDER to its path";

// The line of the log that says what went wrong: the last one naming an error before Blender's
// closing "Error: script failed, ...", i.e. for a Python exception the "IndexError: ..." line
// after the traceback.
std::string lastErrorLine(const fs::path& logPath) {
    std::ifstream in(logPath);
    std::string line, found;
    while (std::getline(in, line)) {
        bool names = line.find("Error") != std::string::npos || line.find("error:") != std::string::npos;
        if (names && line.rfind("Error: script failed", 0) != 0) found = line;
    }
    return found;
}

}  // namespace

std::string blenderProgram() {
    const char* chosen = std::getenv("RTLAB_BLENDER");
    return chosen && *chosen ? chosen : "blender";
}

void runBlenderOrThrow(const std::vector<std::string>& arguments, TemporaryDirectory& work, const std::string& what,
                       double timeLimitSeconds) {
    std::vector<std::string> all{"-b", "--factory-startup", "--python-exit-code", "1"};
    all.insert(all.end(), arguments.begin(), arguments.end());
    runExternalOrThrow(blenderProgram(), all, work, "blender.log", timeLimitSeconds, kInstallHint, what, lastErrorLine);
}

std::string blenderVersion() {
    // Asked once per process: the installed Blender does not change while we run.
    static const std::string version = externalVersion(blenderProgram(), "Blender", 120.0, kInstallHint);
    return version;
}

}  // namespace rtlab
