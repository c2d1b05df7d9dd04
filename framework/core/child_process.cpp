#include "framework/core/child_process.h"

#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <grp.h>
#include <linux/close_range.h>
#include <map>
#include <poll.h>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace rtlab {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
constexpr uid_t kNobody = 65534;

// errno's text; strerror is not safe to call from several threads at once.
std::string errorText(int error) {
    const char* text = strerrordesc_np(error);
    return text ? text : "error " + std::to_string(error);
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (std::string& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
}

// The program's path: as given when it names a folder, else the first executable of that name
// on PATH; empty when there is none.
std::string resolveProgram(const std::string& program, bool searchPath) {
    if (!searchPath || program.find('/') != std::string::npos) return program;
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return "";
}

// Tells the parent why the child cannot become the program (errno) and ends it.
[[noreturn]] void reportAndExit(int report) {
    int error = errno;
    [[maybe_unused]] ssize_t written = write(report, &error, sizeof error);
    _exit(127);
}

// Everything the child does between fork and exec: only async-signal-safe calls, on what the
// parent prepared. A failure is reported through `report` (close-on-exec) as an errno.
[[noreturn]] void becomeChild(const ChildOptions& options, const char* program, char* const* argv, char* const* env, int in, int out,
                              int report) {
    if (options.ownGroup) setpgid(0, 0);
    if (dup2(in, STDIN_FILENO) < 0 || dup2(out, STDOUT_FILENO) < 0 || dup2(out, STDERR_FILENO) < 0) reportAndExit(report);
    // dup2 onto itself keeps close-on-exec (a parent started with a standard stream closed).
    for (int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO})
        if (fcntl(fd, F_SETFD, 0) != 0) reportAndExit(report);
    // Nothing else of ours reaches the program; the report pipe stays open until the exec.
    // Without CLOSE_RANGE_CLOEXEC (Linux before 5.11) every other descriptor is closed.
    if (close_range(3, ~0u, CLOSE_RANGE_CLOEXEC) != 0)
        for (int fd = 3; fd < 65536; ++fd)
            if (fd != report) close(fd);
    if (!options.workDir.empty() && chdir(options.workDir.c_str()) != 0) reportAndExit(report);
    if (options.memoryMiB > 0) {
        rlim_t memory = rlim_t(options.memoryMiB) << 20;
        rlimit as{memory, memory};
        if (setrlimit(RLIMIT_AS, &as) != 0) reportAndExit(report);
    }
    if (options.cpuSeconds > 0) {
        rlimit cpu{rlim_t(options.cpuSeconds), rlim_t(options.cpuSeconds) + 1};
        if (setrlimit(RLIMIT_CPU, &cpu) != 0) reportAndExit(report);
    }
    rlimit none{0, 0};
    if (options.noCoreDumps && setrlimit(RLIMIT_CORE, &none) != 0) reportAndExit(report);
    if (options.asNobody && geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0)) reportAndExit(report);
    execve(program, argv, env);
    reportAndExit(report);
}

// The processes below root, from /proc: what the child started, including those that left its
// process group (a sandbox's own session, a worker in a group of its own).
std::vector<pid_t> descendantsOf(pid_t root) {
    std::multimap<pid_t, pid_t> children;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator("/proc", error)) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || !std::isdigit(static_cast<unsigned char>(name[0]))) continue;
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        if (!std::getline(stat, line)) continue;
        // pid (comm) state ppid ...: comm may hold spaces and parentheses, so parse after the last ')'.
        size_t close = line.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(line.substr(close + 1));
        char state;
        pid_t parent;
        if (rest >> state >> parent) children.emplace(parent, static_cast<pid_t>(std::stol(name)));
    }
    std::vector<pid_t> found, frontier = {root};
    while (!frontier.empty()) {
        pid_t p = frontier.back();
        frontier.pop_back();
        auto [begin, end] = children.equal_range(p);
        for (auto it = begin; it != end; ++it) {
            found.push_back(it->second);
            frontier.push_back(it->second);
        }
    }
    return found;
}

void killOverrun(pid_t pid, const ChildOptions& options) {
    if (!options.ownGroup) {
        kill(pid, SIGKILL);
        return;
    }
    std::vector<pid_t> tree;
    if (options.killDescendants) {
        // Stopped first, so nothing in the tree can start more between listing and killing.
        kill(-pid, SIGSTOP);
        tree = descendantsOf(pid);
        for (pid_t p : tree) kill(p, SIGSTOP);
        for (pid_t p : descendantsOf(pid)) tree.push_back(p);
    }
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL);
    for (pid_t p : tree) kill(p, SIGKILL);
}

// Reads the child's output until it closes (true) or the deadline passes (false): what it or
// anything it started still holds open counts against the limit too.
bool capture(int fd, size_t capacity, Clock::time_point deadline, ChildRun& run) {
    char buffer[65536];
    for (;;) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return false;
        pollfd poller{fd, POLLIN, 0};
        if (poll(&poller, 1, static_cast<int>(std::min<long long>(left, 1000))) <= 0) continue;
        ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;
        size_t room = capacity - std::min(capacity, run.output.size());
        size_t kept = std::min(room, size_t(n));
        run.output.append(buffer, kept);
        run.droppedBytes += size_t(n) - kept;
    }
}

}  // namespace

ChildRun runChild(const ChildOptions& options) {
    ChildRun run;
    auto start = Clock::now();
    auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.wallSeconds));
    auto failed = [&run](const std::string& what, int error) {
        run.startError = what + errorText(error);
        return run;
    };

    // Everything the child needs, made before the fork.
    std::string program = options.argv.empty() ? "" : resolveProgram(options.argv[0], options.searchPath);
    if (program.empty()) {
        return failed("", ENOENT);
    }
    std::vector<std::string> argvStrings = options.argv, envStrings = options.environment.value_or(std::vector<std::string>{});
    std::vector<char*> argv = pointers(argvStrings), env = pointers(envStrings);
    int in = open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (in < 0) return failed("cannot open /dev/null: ", errno);
    int out[2] = {-1, -1};
    if (options.logPath.empty()) {
        if (pipe2(out, O_CLOEXEC) != 0) {
            int error = errno;
            close(in);
            return failed("cannot create a pipe: ", error);
        }
    } else {
        out[1] = open(options.logPath.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | (options.appendLog ? O_APPEND : O_TRUNC), 0644);
        if (out[1] < 0) {
            int error = errno;
            close(in);
            return failed("cannot open " + options.logPath.string() + ": ", error);
        }
    }
    int report[2];
    if (pipe2(report, O_CLOEXEC) != 0) {
        int error = errno;
        close(in), close(out[1]);
        if (out[0] >= 0) close(out[0]);
        return failed("cannot create a pipe: ", error);
    }

    pid_t pid = fork();
    int forkError = errno;
    if (pid == 0) becomeChild(options, program.c_str(), argv.data(), options.environment ? env.data() : environ, in, out[1], report[1]);
    close(in);
    close(out[1]);
    close(report[1]);
    if (pid < 0) {
        close(report[0]);
        if (out[0] >= 0) close(out[0]);
        return failed("cannot fork: ", forkError);
    }
    // Also from here, so a kill that comes before the child's own setpgid still finds the group.
    if (options.ownGroup) setpgid(pid, pid);
    int error = 0;
    ssize_t n;
    while ((n = read(report[0], &error, sizeof error)) < 0 && errno == EINTR) {
    }
    close(report[0]);
    run.started = n == 0;  // the report pipe closed at the exec
    if (n > 0) run.startError = errorText(error);
    else if (n < 0) run.startError = "cannot read why it did not start";

    bool outputClosed = true;
    if (out[0] >= 0) {
        if (run.started) outputClosed = capture(out[0], options.captureBytes, deadline, run);
        close(out[0]);
    }
    // Polled with a growing pause (1 ms to 50 ms): no signal handler of ours is needed, and the
    // poll costs nothing against a child that runs for seconds.
    int status = 0;
    std::chrono::milliseconds pause(1);
    bool waited = true;
    for (;;) {
        pid_t done = outputClosed ? waitpid(pid, &status, WNOHANG) : 0;
        if (done == pid) break;
        if (done < 0 && errno != EINTR) {
            waited = false;  // not ours to wait for any more: no status to report
            break;
        }
        if (!outputClosed || Clock::now() >= deadline) {
            run.timedOut = true;
            killOverrun(pid, options);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::milliseconds(50));
    }
    // Whatever it started and left behind in its group goes with it.
    if (options.ownGroup) kill(-pid, SIGKILL);
    run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!waited) {
        run.started = false;
        run.startError = "lost track of the process";
        return run;
    }
    if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    return run;
}

}  // namespace rtlab
