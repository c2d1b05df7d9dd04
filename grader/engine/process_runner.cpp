#include "grader/engine/process_runner.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtlab::grader {
namespace {

using Clock = std::chrono::steady_clock;
constexpr uid_t kNobody = 65534;

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (std::string& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
}

[[noreturn]] void startChild(std::vector<std::string> argv, std::vector<std::string> environment, const ProcessLimits& limits,
                             int outputFd) {
    setpgid(0, 0);  // its own group, so the whole tree can be killed at once
    int devNull = open("/dev/null", O_RDONLY);
    if (devNull < 0 || dup2(devNull, STDIN_FILENO) < 0 || dup2(outputFd, STDOUT_FILENO) < 0 || dup2(outputFd, STDERR_FILENO) < 0) _exit(126);
    close_range(3, ~0u, 0);
    rlim_t memory = rlim_t(limits.memoryMiB) << 20;
    rlimit as{memory, memory}, cpu{rlim_t(limits.cpuSeconds), rlim_t(limits.cpuSeconds) + 1}, none{0, 0};
    if (setrlimit(RLIMIT_AS, &as) != 0 || setrlimit(RLIMIT_CPU, &cpu) != 0 || setrlimit(RLIMIT_CORE, &none) != 0) _exit(126);
    if (limits.asNobody && geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0)) _exit(126);
    auto args = pointers(argv);
    auto env = pointers(environment);
    execve(args[0], args.data(), env.data());
    _exit(127);
}

}  // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const std::vector<std::string>& environment, const ProcessLimits& limits) {
    ProcessResult result;
    int output[2];
    if (pipe2(output, O_CLOEXEC) != 0) {
        result.failure = std::string("cannot create a pipe: ") + std::strerror(errno);
        return result;
    }
    pid_t pid = fork();
    if (pid < 0) {
        close(output[0]);
        close(output[1]);
        result.failure = std::string("cannot fork: ") + std::strerror(errno);
        return result;
    }
    if (pid == 0) startChild(argv, environment, limits, output[1]);
    close(output[1]);
    setpgid(pid, pid);  // also here, so the group exists before the first kill

    auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.wallSeconds));
    char buffer[65536];
    bool open = true;
    while (open) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
            result.timedOut = true;
            break;
        }
        pollfd fd{output[0], POLLIN, 0};
        if (poll(&fd, 1, static_cast<int>(std::min<long long>(left, 1000))) <= 0) continue;
        ssize_t n = read(output[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        size_t room = limits.outputBytes - std::min(limits.outputBytes, result.output.size());
        size_t kept = std::min(room, size_t(n));
        result.output.append(buffer, kept);
        result.droppedBytes += size_t(n) - kept;
    }
    close(output[0]);
    // The output closed (or time ran out); the process itself gets what is left of the limit.
    int status = 0;
    while (!result.timedOut) {
        pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid) break;
        if (Clock::now() >= deadline) result.timedOut = true;
        else std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (result.timedOut) {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        result.failure = "stopped after the limit of " + std::to_string(int(limits.wallSeconds)) + " s";
        return result;
    }
    kill(-pid, SIGKILL);  // anything it left behind in its group
    if (WIFEXITED(status)) {
        result.exitCode = WEXITSTATUS(status);
        if (result.exitCode == 127) result.failure = "could not be started";
        else if (result.exitCode != 0) result.failure = "exit status " + std::to_string(result.exitCode);
    } else if (WIFSIGNALED(status)) {
        result.signal = WTERMSIG(status);
        result.failure = std::string("killed by signal ") + (sigabbrev_np(result.signal) ? sigabbrev_np(result.signal) : "?");
    }
    return result;
}

}  // namespace rtlab::grader
