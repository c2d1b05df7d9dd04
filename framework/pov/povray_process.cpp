#include "framework/pov/povray_process.h"

#include "framework/external/external_process.h"

#include <fstream>

namespace rtlab {
namespace fs = std::filesystem;

namespace {

constexpr const char* kInstallHint = "install it with scripts/install-deps";

// POV-Ray's first line that says what went wrong, to quote in a one-line error.
std::string firstErrorLine(const fs::path& logPath) {
    std::ifstream in(logPath);
    std::string line;
    while (std::getline(in, line)) {
        bool isError = line.find("Error") != std::string::npos || line.find("error") != std::string::npos;
        if (isError && line.find("user configuration file") == std::string::npos) return line;
    }
    return "";
}

}  // namespace

void runPovrayOrThrow(const std::vector<std::string>& arguments, TemporaryDirectory& work,
                      const std::string& what) {
    runExternalOrThrow("povray", arguments, work, "povray.log", kPovrayTimeLimitSeconds, kInstallHint, what,
                       firstErrorLine);
}

std::string povrayVersion() {
    // Asked once per process: the installed POV-Ray does not change while we run.
    static const std::string version = externalVersion("povray", "POV-Ray", kPovrayTimeLimitSeconds, kInstallHint);
    return version;
}

}  // namespace rtlab
