#include "framework/external/external_process.h"

#include "framework/core/child_process.h"
#include "framework/core/error.h"

#include <fstream>
#include <sstream>

namespace rtlab {
namespace fs = std::filesystem;

ExternalRun runExternal(const std::string& program, const std::vector<std::string>& arguments,
                        const fs::path& workDir, const fs::path& logPath, double timeLimitSeconds,
                        const std::string& hint) {
    ChildOptions options;
    options.argv = {program};
    options.argv.insert(options.argv.end(), arguments.begin(), arguments.end());
    options.searchPath = true;
    options.workDir = workDir;
    options.logPath = fs::absolute(logPath);
    options.wallSeconds = timeLimitSeconds;
    options.ownGroup = false;
    ChildRun child = runChild(options);
    if (!child.started) throw Error("cannot start " + program + ": " + child.startError + " (" + hint + ")");
    ExternalRun run;
    run.timedOut = child.timedOut;
    run.exitStatus = child.signal != 0 ? 128 + child.signal : child.exitCode;
    run.seconds = child.seconds;
    return run;
}

void runExternalOrThrow(const std::string& program, const std::vector<std::string>& arguments, TemporaryDirectory& work,
                        const std::string& logName, double timeLimitSeconds, const std::string& hint,
                        const std::string& what, const ErrorLineFinder& errorLine) {
    fs::path logPath = work.path() / logName;
    ExternalRun run = runExternal(program, arguments, work.path(), logPath, timeLimitSeconds, hint);
    if (run.succeeded()) return;
    work.keep();
    if (run.timedOut)
        throw Error(program + " took longer than " + secondsText(timeLimitSeconds) + " s " + what +
                    " (killed); log: " + logPath.string());
    std::string reason = errorLine(logPath);
    throw Error(program + " failed (exit " + std::to_string(run.exitStatus) + ") " + what +
                (reason.empty() ? "" : ": " + reason) + "; log: " + logPath.string());
}

std::string externalVersion(const std::string& program, const std::string& name, double timeLimitSeconds,
                            const std::string& hint) {
    TemporaryDirectory work("rtlab-version");
    fs::path logPath = work.path() / "version.txt";
    runExternal(program, {"--version"}, work.path(), logPath, timeLimitSeconds, hint);
    std::ifstream in(logPath);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(name + " ", 0) == 0) return line;
    throw Error(program + " --version printed no '" + name + " <version>' line");
}

std::string secondsText(double seconds) {
    std::ostringstream out;
    out << seconds;
    return out.str();
}

}  // namespace rtlab
