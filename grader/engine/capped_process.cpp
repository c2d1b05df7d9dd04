#include "grader/engine/capped_process.h"

#include "framework/core/child_process.h"

#include <cstring>
#include <fstream>

namespace rtlab::grader {

std::string CappedRun::describe(double capSeconds) const {
    if (!started) return "could not be started";
    if (timedOut) return "took longer than " + std::to_string(static_cast<long>(capSeconds)) + " s (killed)";
    if (signal != 0) return std::string("killed by ") + (sigabbrev_np(signal) ? "SIG" + std::string(sigabbrev_np(signal)) : "a signal");
    return "exited with status " + std::to_string(exitCode);
}

CappedRun runCapped(const std::vector<std::string>& arguments, const std::string& logPath, double capSeconds) {
    ChildOptions options;
    options.argv = arguments;
    options.logPath = logPath;
    options.appendLog = true;
    options.wallSeconds = capSeconds;
    options.killDescendants = true;
    ChildRun child = runChild(options);
    CappedRun run;
    run.started = child.started;
    run.timedOut = child.timedOut;
    run.seconds = child.seconds;
    if (!child.timedOut) {
        run.exitCode = child.exitCode;
        run.signal = child.signal;
    }
    return run;
}

std::string tailOfFile(const std::string& path, size_t maxLines, size_t maxBytes) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return "";
    std::streamoff size = in.tellg();
    std::streamoff from = size > static_cast<std::streamoff>(maxBytes) ? size - static_cast<std::streamoff>(maxBytes) : 0;
    in.seekg(from);
    std::string text(static_cast<size_t>(size - from), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    while (!text.empty() && text.back() == '\n') text.pop_back();
    size_t begin = text.size();
    for (size_t lines = 0; begin > 0 && lines < maxLines; --begin)
        if (text[begin - 1] == '\n' && ++lines == maxLines) break;
    return text.substr(begin);
}

}  // namespace rtlab::grader
