#include "grader/engine/sandbox_start.h"

#include "grader/engine/system_call_filter.h"
#include "grader/wire/worker_protocol.h"

#include <fcntl.h>
#include <grp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <charconv>
#include <csignal>
#include <stdexcept>

namespace rtlab::grader {
namespace {

constexpr uid_t kNobody = 65534;

uint64_t parseNumber(const char* text) {
    uint64_t value = 0;
    const char* end = text + std::char_traits<char>::length(text);
    auto [stop, error] = std::from_chars(text, end, value);
    if (error != std::errc() || stop != end || stop == text) throw std::invalid_argument(std::string("not a number: ") + text);
    return value;
}

}  // namespace

std::string sandboxStartPath() { return RTLAB_SANDBOX_START; }

std::vector<std::string> sandboxStartArguments(const SandboxStart& start) {
    return {"rtlab-sandbox-start", start.worker, std::to_string(start.addressSpace), std::to_string(start.cpuSeconds),
            std::to_string(start.grader)};
}

SandboxStart parseSandboxStart(int argc, const char* const* argv) {
    if (argc != 5) throw std::invalid_argument("usage: rtlab-sandbox-start WORKER ADDRESS-SPACE CPU-SECONDS GRADER-PID (started by the grader)");
    SandboxStart start;
    start.worker = argv[1];
    start.addressSpace = parseNumber(argv[2]);
    start.cpuSeconds = parseNumber(argv[3]);
    start.grader = static_cast<pid_t>(parseNumber(argv[4]));
    return start;
}

void startSandboxedWorker(const SandboxStart& start) {
    int filterFd = -1;
    try {
        filterFd = exportSystemCallFilter(worker::kResultFd, getpid());
    } catch (...) {
        _exit(worker::kExitSandboxFailed);
    }
    // The filter's file is close-on-exec: a duplicate is not, and one already in place is made so.
    bool inPlace = filterFd == worker::kFilterFd ? fcntl(worker::kFilterFd, F_SETFD, 0) == 0 : dup2(filterFd, worker::kFilterFd) == worker::kFilterFd;
    if (!inPlace) _exit(worker::kExitSandboxFailed);
    close_range(worker::kFilterFd + 1, ~0u, 0);
    // Opened while still the grader's user, so the worker runs wherever the build lives (a
    // folder nobody may not enter, say); executing it by descriptor checks only the file.
    int executable = open(start.worker.c_str(), O_RDONLY | O_CLOEXEC);
    if (executable < 0) _exit(worker::kExitSandboxFailed);

    rlimit memory{start.addressSpace, start.addressSpace};
    rlimit cpu{start.cpuSeconds, start.cpuSeconds + 1};
    rlimit none{0, 0};
    rlimit files{8, 8};
    if (setrlimit(RLIMIT_AS, &memory) != 0 || setrlimit(RLIMIT_CPU, &cpu) != 0 || setrlimit(RLIMIT_CORE, &none) != 0 ||
        setrlimit(RLIMIT_FSIZE, &none) != 0 || setrlimit(RLIMIT_NOFILE, &files) != 0)
        _exit(worker::kExitSandboxFailed);
    // A grader running as root hands the worker to nobody: no file of the grader's is its own.
    if (geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0))
        _exit(worker::kExitSandboxFailed);
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // after setuid, which clears it
    if (getppid() != start.grader) _exit(worker::kExitSandboxFailed);  // the grader died before that
    char name[] = "rtlab-worker";
    char* argv[] = {name, nullptr};
    char* envp[] = {nullptr};
    char empty[] = "";
    syscall(SYS_execveat, executable, empty, argv, envp, AT_EMPTY_PATH);
    _exit(worker::kExitSandboxFailed);
}

}  // namespace rtlab::grader
