#include "framework/external/external_process.h"

#include "framework/core/error.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace rtlab {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

int statusOf(int waitStatus) {
    if (WIFEXITED(waitStatus)) return WEXITSTATUS(waitStatus);
    return 128 + (WIFSIGNALED(waitStatus) ? WTERMSIG(waitStatus) : 0);
}

}  // namespace

ExternalRun runExternal(const std::string& program, const std::vector<std::string>& arguments,
                        const fs::path& workDir, const fs::path& logPath, double timeLimitSeconds,
                        const std::string& hint) {
    std::vector<std::string> argvStrings{program};
    argvStrings.insert(argvStrings.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& s : argvStrings) argv.push_back(s.data());
    argv.push_back(nullptr);

    // posix_spawn rather than fork: safe in a multi-threaded process.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, workDir.c_str());
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, fs::absolute(logPath).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = 0;
    Clock::time_point start = Clock::now();
    int spawnError = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawnError != 0)
        throw Error("cannot start " + program + ": " + std::strerror(spawnError) + " (" + hint + ")");

    // Polled with a growing pause (1 ms to 50 ms): a render takes seconds, so the poll costs
    // nothing, and no signal handler of ours is needed.
    Clock::time_point deadline =
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeLimitSeconds));
    ExternalRun run;
    std::chrono::milliseconds pause(1);
    int status = 0;
    for (;;) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) throw Error("waiting for " + program + ": " + std::strerror(errno));
        if (Clock::now() >= deadline) {
            run.timedOut = true;
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::milliseconds(50));
    }
    run.exitStatus = statusOf(status);
    run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
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
