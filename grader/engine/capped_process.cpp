#include "grader/engine/capped_process.h"

#include <chrono>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtlab::grader {
namespace {

// Between polls of waitpid: short against a cap of seconds, long enough to cost nothing.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

[[noreturn]] void execInChild(const std::vector<char*>& argv, const std::string& logPath) {
    setpgid(0, 0);
    int in = open("/dev/null", O_RDONLY);
    int log = open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (in < 0 || log < 0) _exit(127);
    dup2(in, STDIN_FILENO);
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
}

// The processes below root, from /proc: what the child started, including those that left its
// process group (a sandbox's own session, a worker the grading child runs in a group of its own).
std::vector<pid_t> descendantsOf(pid_t root) {
    std::multimap<pid_t, pid_t> children;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
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

// Stops the tree first so nothing in it can start more processes between listing and killing.
void killTree(pid_t root) {
    kill(-root, SIGSTOP);
    std::vector<pid_t> tree = descendantsOf(root);
    for (pid_t p : tree) kill(p, SIGSTOP);
    for (pid_t p : descendantsOf(root)) tree.push_back(p);
    kill(-root, SIGKILL);
    kill(root, SIGKILL);
    for (pid_t p : tree) kill(p, SIGKILL);
}

}  // namespace

std::string CappedRun::describe(double capSeconds) const {
    if (!started) return "could not be started";
    if (timedOut) return "took longer than " + std::to_string(static_cast<long>(capSeconds)) + " s (killed)";
    if (signal != 0) return std::string("killed by ") + (sigabbrev_np(signal) ? "SIG" + std::string(sigabbrev_np(signal)) : "a signal");
    return "exited with status " + std::to_string(exitCode);
}

CappedRun runCapped(const std::vector<std::string>& arguments, const std::string& logPath, double capSeconds) {
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    auto start = std::chrono::steady_clock::now();
    auto deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(capSeconds));
    CappedRun run;
    pid_t pid = fork();
    if (pid < 0) return run;
    if (pid == 0) execInChild(argv, logPath);
    // Also from here, so a kill that comes before the child's own setpgid still finds the group.
    setpgid(pid, pid);
    run.started = true;
    int status = 0;
    for (;;) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) {
            run.started = false;
            return run;
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            run.timedOut = true;
            killTree(pid);
            waitpid(pid, &status, 0);  // SIGKILL cannot be caught: this returns at once
            break;
        }
        std::this_thread::sleep_for(kPollInterval);
    }
    // Whatever the child started and left behind in its group goes with it.
    kill(-pid, SIGKILL);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (run.timedOut) return run;
    if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    if (run.exitCode == 127) run.started = false;
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
