#include "grader/sandbox.h"

#include "framework/core/error.h"
#include "grader/system_call_filter.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <poll.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtlab::grader {
namespace {

using Clock = std::chrono::steady_clock;

// What a child writes on the result pipe: a 13-byte header (kind, phase, payload length)
// followed by the payload.
enum class RecordKind : uint8_t { PhaseStart = 1, PhaseData, NotStarted, Failed, OutOfMemory, Forbidden, Done };
constexpr size_t kHeaderSize = 1 + 4 + 8;
constexpr uint64_t kMaxPayload = uint64_t(1) << 30;
constexpr size_t kMaxCapturedOutput = 4096;
constexpr int kResultFd = 3;  // where the child keeps the result pipe
// The status a child ends with when student code calls exit(): the handler registered last
// runs first and ends the process before the grader's own exit handlers (which may wait for
// threads the child does not have) can run.
constexpr int kExitCalled = 86;

volatile sig_atomic_t currentPhase = 0;

bool writeAll(int fd, const void* data, size_t size) {
    const auto* p = static_cast<const uint8_t*>(data);
    while (size > 0) {
        ssize_t n = write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

// Async-signal-safe (only write()), so the SIGSYS handler can use it.
void sendRecord(RecordKind kind, uint32_t phase, const void* payload, uint64_t size) {
    uint8_t header[kHeaderSize];
    header[0] = static_cast<uint8_t>(kind);
    std::memcpy(header + 1, &phase, 4);
    std::memcpy(header + 5, &size, 8);
    writeAll(kResultFd, header, kHeaderSize);
    if (size > 0) writeAll(kResultFd, payload, size);
}

void sendText(RecordKind kind, uint32_t phase, const std::string& text) {
    sendRecord(kind, phase, text.data(), text.size());
}

void onForbiddenSystemCall(int, siginfo_t* info, void*) {
    int32_t number = info->si_syscall;
    sendRecord(RecordKind::Forbidden, static_cast<uint32_t>(currentPhase), &number, sizeof number);
    syscall(SYS_exit_group, 125);
}

// Runs one phase and reports how it ended; true when it completed.
bool runPhase(const ChildPhase& phase, uint32_t index) {
    currentPhase = static_cast<sig_atomic_t>(index);
    sendRecord(RecordKind::PhaseStart, index, nullptr, 0);
    try {
        ByteWriter out;
        phase.run(out);
        sendRecord(RecordKind::PhaseData, index, out.bytes().data(), out.bytes().size());
        return true;
    } catch (const NotImplemented& e) {
        sendText(RecordKind::NotStarted, index, e.stub);
    } catch (const std::bad_alloc&) {
        sendRecord(RecordKind::OutOfMemory, index, nullptr, 0);
    } catch (const std::exception& e) {
        sendText(RecordKind::Failed, index, std::string("threw an exception: ") + e.what());
    } catch (...) {
        sendText(RecordKind::Failed, index, "threw an exception that is not a std::exception");
    }
    return false;
}

[[noreturn]] void runChild(std::span<const ChildPhase> phases, size_t first, const std::vector<bool>& skip,
                           const SandboxLimits& limits, int resultFd, int outputFd, uint64_t addressSpaceLimit) {
    int devNull = open("/dev/null", O_RDONLY);
    dup2(devNull, STDIN_FILENO);
    dup2(outputFd, STDOUT_FILENO);
    dup2(outputFd, STDERR_FILENO);
    dup2(resultFd, kResultFd);
    close_range(kResultFd + 1, ~0u, 0);

    rlimit memory{addressSpaceLimit, addressSpaceLimit};
    rlimit cpu{static_cast<rlim_t>(limits.cpuSeconds), static_cast<rlim_t>(limits.cpuSeconds + 1)};
    rlimit none{0, 0};
    setrlimit(RLIMIT_AS, &memory);
    setrlimit(RLIMIT_CPU, &cpu);
    setrlimit(RLIMIT_CORE, &none);
    setrlimit(RLIMIT_FSIZE, &none);

    struct sigaction action {};
    action.sa_sigaction = onForbiddenSystemCall;
    action.sa_flags = SA_SIGINFO;
    sigaction(SIGSYS, &action, nullptr);
    try {
        installSystemCallFilter(kResultFd);
    } catch (const std::exception& e) {
        sendText(RecordKind::Failed, 0, std::string("the grader could not install its sandbox: ") + e.what());
        _exit(1);
    }

    std::atexit([] { _exit(kExitCalled); });
    if (runPhase(phases[0], 0))
        for (size_t k = first; k < phases.size(); ++k)
            if (!skip[k]) runPhase(phases[k], static_cast<uint32_t>(k));
    sendRecord(RecordKind::Done, 0, nullptr, 0);
    _exit(0);
}

uint64_t addressSpaceInUse() {
    std::ifstream statm("/proc/self/statm");
    uint64_t pages = 0;
    statm >> pages;
    return pages * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

std::string signalName(int sig) {
    const char* abbreviation = sigabbrev_np(sig);
    return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(sig);
}

std::string formatSeconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", s);
    return buffer;
}

// The parent's side of one child: reads records until the child is done, dies or overruns.
class ChildSession {
public:
    ChildSession(std::span<const ChildPhase> phases, const SandboxLimits& limits, SandboxRun& run)
        : phases_(phases), limits_(limits), run_(run), outcomes_(phases.size()), reported_(phases.size(), false) {}

    // Runs phase 0 and the phases in [first, n) that are not skipped.
    void execute(size_t first, const std::vector<bool>& skip) {
        int resultPipe[2], outputPipe[2];
        if (pipe2(resultPipe, O_CLOEXEC) != 0 || pipe2(outputPipe, O_CLOEXEC) != 0)
            throw Error(std::string("grader: cannot create a pipe: ") + std::strerror(errno));
        uint64_t limit = addressSpaceInUse() + (uint64_t(limits_.memoryMiB) << 20);
        std::cout.flush();
        std::fflush(nullptr);
        pid_t pid = fork();
        if (pid < 0) throw Error(std::string("grader: cannot fork: ") + std::strerror(errno));
        if (pid == 0) {
            close(resultPipe[0]);
            close(outputPipe[0]);
            runChild(phases_, first, skip, limits_, resultPipe[1], outputPipe[1], limit);
        }
        close(resultPipe[1]);
        close(outputPipe[1]);
        pid_ = pid;
        phaseStart_ = Clock::now();
        readUntilDone(resultPipe[0], outputPipe[0]);
        close(resultPipe[0]);
        close(outputPipe[0]);
        int status = reap();
        judgeEnding(status);
    }

    const std::vector<PhaseOutcome>& outcomes() const { return outcomes_; }
    const std::vector<bool>& reported() const { return reported_; }

private:
    Clock::time_point deadline() const {
        return phaseStart_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.wallSeconds));
    }

    void readUntilDone(int resultFd, int outputFd) {
        pollfd fds[2] = {{resultFd, POLLIN, 0}, {outputFd, POLLIN, 0}};
        bool open[2] = {true, true};
        while ((open[0] || open[1]) && !malformed_) {
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline() - Clock::now()).count();
            if (left <= 0) {
                overran_ = true;
                return;
            }
            for (int i = 0; i < 2; ++i) fds[i].fd = open[i] ? (i == 0 ? resultFd : outputFd) : -1;
            int ready = poll(fds, 2, static_cast<int>(std::min<long long>(left, 1000)));
            if (ready < 0 && errno != EINTR) throw Error(std::string("grader: poll failed: ") + std::strerror(errno));
            uint8_t buffer[65536];
            for (int i = 0; i < 2; ++i) {
                if (!open[i] || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
                ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
                if (n < 0 && errno == EINTR) continue;
                if (n <= 0) {
                    open[i] = false;
                    continue;
                }
                if (i == 0) {
                    pending_.insert(pending_.end(), buffer, buffer + n);
                    parseRecords();
                } else {
                    size_t room = kMaxCapturedOutput - std::min(kMaxCapturedOutput, run_.output.size());
                    run_.output.append(reinterpret_cast<char*>(buffer), std::min<size_t>(room, size_t(n)));
                }
            }
        }
    }

    void parseRecords() {
        size_t position = 0;
        while (pending_.size() - position >= kHeaderSize) {
            const uint8_t* header = pending_.data() + position;
            auto kind = static_cast<RecordKind>(header[0]);
            uint32_t phase;
            uint64_t size;
            std::memcpy(&phase, header + 1, 4);
            std::memcpy(&size, header + 5, 8);
            bool known = header[0] >= uint8_t(RecordKind::PhaseStart) && header[0] <= uint8_t(RecordKind::Done);
            if (!known || phase >= phases_.size() || size > kMaxPayload) {
                malformed_ = true;
                return;
            }
            if (pending_.size() - position - kHeaderSize < size) break;
            std::span<const uint8_t> payload(header + kHeaderSize, size);
            handle(kind, phase, payload);
            position += kHeaderSize + size;
            if (malformed_) return;
        }
        pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(position));
    }

    void handle(RecordKind kind, uint32_t phase, std::span<const uint8_t> payload) {
        if (kind == RecordKind::Done) {
            done_ = true;
            return;
        }
        if (kind == RecordKind::PhaseStart) {
            current_ = phase;
            phaseStart_ = Clock::now();
            return;
        }
        if (reported_[phase]) {  // a second verdict for one phase: the child writes to our pipe
            malformed_ = true;
            return;
        }
        PhaseOutcome& outcome = outcomes_[phase];
        const std::string& stub = phases_[phase].stub;
        std::string text(payload.begin(), payload.end());
        switch (kind) {
        case RecordKind::PhaseData:
            outcome.status = PhaseStatus::Completed;
            outcome.data.assign(payload.begin(), payload.end());
            break;
        case RecordKind::NotStarted:
            outcome.status = PhaseStatus::NotStarted;
            outcome.reason = "not started: " + text + " throws NotImplemented";
            break;
        case RecordKind::Failed:
            outcome.status = PhaseStatus::Failed;
            outcome.reason = text + " (in " + stub + ")";
            break;
        case RecordKind::OutOfMemory:
            outcome.status = PhaseStatus::OutOfMemory;
            outcome.reason = "exceeded the memory limit of " + std::to_string(limits_.memoryMiB) + " MiB in " + stub;
            break;
        case RecordKind::Forbidden: {
            int32_t number = -1;
            if (payload.size() == sizeof number) std::memcpy(&number, payload.data(), sizeof number);
            outcome.status = PhaseStatus::Forbidden;
            outcome.reason = "made a forbidden system call (" + systemCallName(number) + ") in " + stub +
                             ": student code may not open files, start processes or use the network";
            break;
        }
        default: malformed_ = true; return;
        }
        outcome.seconds = std::chrono::duration<double>(Clock::now() - phaseStart_).count();
        reported_[phase] = true;
    }

    int reap() {
        int status = 0;
        while (!overran_ && !malformed_) {
            pid_t r = waitpid(pid_, &status, WNOHANG);
            if (r == pid_) return status;
            if (Clock::now() >= deadline()) {
                overran_ = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        return status;
    }

    // The phase the child was in when it ended without reporting it, if any. A child that
    // ends right after reporting a phase (a forbidden call ends it) is blamed for nothing.
    std::optional<size_t> unfinishedPhase() const {
        if (!current_) return 0;
        if (!reported_[*current_]) return current_;
        return std::nullopt;
    }

    void judgeEnding(int status) {
        auto phase = unfinishedPhase();
        if (!phase) return;
        PhaseOutcome& outcome = outcomes_[*phase];
        const std::string& stub = phases_[*phase].stub;
        if (malformed_) {
            outcome.status = PhaseStatus::Failed;
            outcome.reason = "sent malformed results from " + stub;
        } else if (overran_) {
            outcome.status = PhaseStatus::TimedOut;
            outcome.reason = "timed out after " + formatSeconds(limits_.wallSeconds) + " s in " + stub;
        } else if (WIFSIGNALED(status)) {
            int sig = WTERMSIG(status);
            if (sig == SIGXCPU || sig == SIGKILL) {
                outcome.status = PhaseStatus::TimedOut;
                outcome.reason = "used more than " + std::to_string(limits_.cpuSeconds) + " s of CPU time in " + stub;
            } else if (sig == SIGSYS) {
                outcome.status = PhaseStatus::Forbidden;
                outcome.reason = "made a forbidden system call in " + stub;
            } else {
                outcome.status = PhaseStatus::Crashed;
                outcome.reason = "crashed with " + signalName(sig) + " in " + stub;
            }
        } else {
            outcome.status = PhaseStatus::NoResults;
            int code = WEXITSTATUS(status);
            outcome.reason = "child exited without results (" +
                             (code == kExitCalled ? std::string("it called exit()") : "exit status " + std::to_string(code)) + ") in " + stub;
        }
        outcome.seconds = std::chrono::duration<double>(Clock::now() - phaseStart_).count();
        reported_[*phase] = true;
    }

public:
    bool finished() const { return done_ && !overran_ && !malformed_; }

private:
    std::span<const ChildPhase> phases_;
    const SandboxLimits& limits_;
    SandboxRun& run_;
    std::vector<PhaseOutcome> outcomes_;
    std::vector<bool> reported_;
    std::vector<uint8_t> pending_;
    pid_t pid_ = -1;
    Clock::time_point phaseStart_;
    std::optional<size_t> current_;
    bool done_ = false;
    bool overran_ = false;
    bool malformed_ = false;
};

}  // namespace

bool TimeoutStrikes::exhausted(const std::string& stub) const {
    auto it = counts_.find(stub);
    return it != counts_.end() && it->second >= kLimit;
}

SandboxRun runSandboxed(std::span<const ChildPhase> phases, const SandboxLimits& limits, TimeoutStrikes* strikes) {
    SandboxRun run;
    run.phases.resize(phases.size());
    std::vector<bool> have(phases.size(), false), skipped(phases.size(), false);
    for (size_t k = 0; k < phases.size() && strikes; ++k)
        if (strikes->exhausted(phases[k].stub)) {
            skipped[k] = have[k] = true;
            run.phases[k] = PhaseOutcome{PhaseStatus::TimedOut, {},
                                         "not run: " + phases[k].stub + " already timed out " + std::to_string(TimeoutStrikes::kLimit) +
                                             " times (limit " + formatSeconds(limits.wallSeconds) + " s per test)",
                                         0.0};
        }
    if (skipped[0]) {
        for (size_t k = 1; k < phases.size(); ++k) run.phases[k] = run.phases[0];
        return run;
    }
    size_t first = 1;
    while (true) {
        ChildSession child(phases, limits, run);
        child.execute(first, skipped);
        for (size_t k = 0; k < phases.size(); ++k)
            if (child.reported()[k] && !have[k]) {
                run.phases[k] = child.outcomes()[k];
                have[k] = true;
            }
        // Without the set-up nothing else can run: every phase shares its verdict.
        const PhaseOutcome& setup = child.reported()[0] ? child.outcomes()[0] : run.phases[0];
        if (setup.status != PhaseStatus::Completed) {
            for (size_t k = 1; k < phases.size(); ++k)
                if (!have[k]) {
                    run.phases[k] = PhaseOutcome{setup.status, {}, setup.reason, 0.0};
                    have[k] = true;
                }
            break;
        }
        // Phases run in order, so the next child starts at the first one without a verdict.
        if (child.finished()) break;
        auto next = std::find(have.begin() + 1, have.end(), false);
        if (next == have.end()) break;
        first = static_cast<size_t>(next - have.begin());
    }
    for (size_t k = 0; k < phases.size(); ++k) {
        if (!have[k]) run.phases[k] = PhaseOutcome{PhaseStatus::NoResults, {}, "child exited without results in " + phases[k].stub, 0.0};
        // A phase that inherited the set-up's timeout did not time out itself.
        bool ownVerdict = k == 0 || run.phases[0].status == PhaseStatus::Completed;
        if (strikes && ownVerdict && !skipped[k] && run.phases[k].status == PhaseStatus::TimedOut) strikes->record(phases[k].stub);
    }
    return run;
}

const char* phaseStatusName(PhaseStatus status) {
    switch (status) {
    case PhaseStatus::Completed: return "completed";
    case PhaseStatus::NotStarted: return "not started";
    case PhaseStatus::Failed: return "failed";
    case PhaseStatus::Crashed: return "crashed";
    case PhaseStatus::TimedOut: return "timed out";
    case PhaseStatus::OutOfMemory: return "out of memory";
    case PhaseStatus::Forbidden: return "forbidden system call";
    case PhaseStatus::NoResults: return "no results";
    }
    return "?";
}

}  // namespace rtlab::grader
