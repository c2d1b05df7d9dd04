#include "grader/engine/sandbox.h"

#include "framework/core/error.h"
#include "grader/engine/request_queue.h"
#include "grader/engine/sandbox_start.h"
#include "grader/engine/system_call_filter.h"
#include "grader/engine/worker_conversation.h"
#include "grader/wire/task_inputs.h"
#include "grader/wire/worker_protocol.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <time.h>
#include <unistd.h>
#include <utility>

namespace rtlab::grader {
namespace {

using Clock = std::chrono::steady_clock;
using worker::RecordKind;

constexpr size_t kMaxCapturedOutput = 4096;
constexpr uint64_t kWorkerBaseMiB = 64;  // the worker's own code, stacks and the C runtime
// After the end of its request a worker has this long to say Done and exit.
constexpr double kEndSeconds = 2.0;
// A phase's limit is CPU time, and its wall-clock time may be this many times the limit: room
// for a machine with four runnable processes per core.
constexpr double kLoadAllowance = 4.0;

std::string signalName(int sig) {
    const char* abbreviation = sigabbrev_np(sig);
    return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(sig);
}

std::string formatSeconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", s);
    return buffer;
}

Clock::duration seconds(double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); }

// CPU time of a process and all its threads, live and ended, as the kernel counts it (in
// nanoseconds, unlike the clock ticks of /proc/PID/stat).
std::optional<double> processCpuSeconds(pid_t pid) {
    clockid_t clock;
    timespec now{};
    if (clock_getcpuclockid(pid, &clock) != 0 || clock_gettime(clock, &now) != 0) return std::nullopt;
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Spawns rtlab-sandbox-start with the worker's pipes on descriptors 0-3 (sandbox_start.h).
// posix_spawn shares the grader's memory until the exec instead of copying its page tables.
pid_t spawnSandboxStart(const WorkerSpec& spec, int requestFd, int resultFd, int outputFd, uint64_t addressSpace) {
    SandboxStart start{spec.path, addressSpace, static_cast<uint64_t>(spec.limits.cpuSeconds), getpid()};
    std::vector<std::string> arguments = sandboxStartArguments(start);
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);
    char* envp[] = {nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // The sources are the grader's pipes, all above 2, duplicated before descriptor 3 is
    // replaced; the duplicates lose close-on-exec, the originals keep it.
    posix_spawn_file_actions_adddup2(&actions, requestFd, 0);
    posix_spawn_file_actions_adddup2(&actions, outputFd, 1);
    posix_spawn_file_actions_adddup2(&actions, outputFd, 2);
    posix_spawn_file_actions_adddup2(&actions, resultFd, worker::kResultFd);
    pid_t pid = -1;
    const std::string launcher = sandboxStartPath();
    int error = posix_spawn(&pid, launcher.c_str(), &actions, nullptr, argv.data(), envp);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw Error("grader: cannot start " + launcher + ": " + std::strerror(error));
    return pid;
}

// A pipe of 1 MiB instead of 64 KiB carries a phase's input (up to megabytes of triangles
// and rays) in a sixteenth of the wake-ups; a kernel that refuses keeps the default.
constexpr int kPipeBytes = 1 << 20;

// Starts a worker whose address space allows its base, the memory limit and twice the input
// of each phase it may be asked to run.
StartedWorker::Process spawnWorker(const WorkerSpec& spec, std::span<const ChildPhase> phases, std::span<const size_t> order) {
    uint64_t addressSpace = (kWorkerBaseMiB + uint64_t(spec.limits.memoryMiB)) << 20;
    for (size_t k : order) addressSpace += 2 * phases[k].input.size();
    int requestPipe[2], resultPipe[2], outputPipe[2];
    if (pipe2(requestPipe, O_CLOEXEC) != 0 || pipe2(resultPipe, O_CLOEXEC) != 0 || pipe2(outputPipe, O_CLOEXEC) != 0)
        throw Error(std::string("grader: cannot create a pipe: ") + std::strerror(errno));
    fcntl(requestPipe[1], F_SETPIPE_SZ, kPipeBytes);
    fcntl(resultPipe[1], F_SETPIPE_SZ, kPipeBytes);
    pid_t pid = spawnSandboxStart(spec, requestPipe[0], resultPipe[1], outputPipe[1], addressSpace);
    close(requestPipe[0]);
    close(resultPipe[1]);
    close(outputPipe[1]);
    fcntl(requestPipe[1], F_SETFL, O_NONBLOCK);
    return {pid, requestPipe[1], resultPipe[0], outputPipe[0]};
}

std::vector<size_t> allPhases(size_t count) {
    std::vector<size_t> order(count);
    for (size_t k = 0; k < count; ++k) order[k] = k;
    return order;
}

// The grader's side of one worker: streams the phases' requests, reads records until the
// worker is done, dies or overruns a deadline.
class WorkerSession {
public:
    WorkerSession(const WorkerSpec& spec, std::span<const ChildPhase> phases, SandboxRun& run)
        : spec_(spec), phases_(phases), run_(run), outcomes_(phases.size()), reported_(phases.size(), false) {}

    // Runs phase 0 and then the phases in order, in `started` if given, else in a new worker.
    void execute(std::vector<size_t> order, std::optional<StartedWorker> started) {
        order_ = order;
        conversation_.emplace(std::move(order));
        StartedWorker::Process process = started ? started->take() : spawnWorker(spec_, phases_, order_);
        pid_ = process.pid;
        requestFd_ = process.requestFd;
        queueRequest();
        converse(process.resultFd, process.outputFd);
        if (requestFd_ >= 0) close(requestFd_);
        close(process.resultFd);
        close(process.outputFd);
        judgeEnding(reap());
    }

    const std::vector<PhaseOutcome>& outcomes() const { return outcomes_; }
    const std::vector<bool>& reported() const { return reported_; }
    bool finished() const { return conversation_->done() && !overran_ && !malformed(); }

private:
    bool malformed() const { return conversation_->malformed(); }

    // Queues the request of the conversation's current phase, or the end of the request after
    // the last one. Each phase's deadline starts here and is set once: no record moves it.
    void queueRequest() {
        size_t step = conversation_->step();
        if (step >= order_.size()) {
            request_.put<uint32_t>(worker::kEndOfRequest);
            deadline_ = Clock::now() + seconds(kEndSeconds);
            cpuAtPhase_.reset();  // the end has a wall-clock deadline only
            return;
        }
        const ChildPhase& phase = phases_[order_[step]];
        request_.put<uint32_t>(static_cast<uint32_t>(order_[step]));
        request_.put<uint32_t>(static_cast<uint32_t>(phase.task.size()));
        request_.own({reinterpret_cast<const uint8_t*>(phase.task.data()), phase.task.size()});
        request_.put<uint64_t>(phase.input.size());
        request_.view(phase.input);
        phaseRequestedAt_ = Clock::now();
        // The set-up's CPU time counts from the worker's start: a worker started ahead
        // (StartedWorker) may have run code before this request, and that code is the set-up's,
        // so its first deadline comes as much earlier as the CPU time it has already used.
        double usedAhead = 0.0;
        if (step == 0) {
            usedAhead = processCpuSeconds(pid_).value_or(0.0);
            cpuAtPhase_ = 0.0;
        } else {
            cpuAtPhase_ = processCpuSeconds(pid_);
        }
        deadline_ = phaseRequestedAt_ + seconds(std::max(0.0, spec_.limits.wallSeconds - usedAhead));
    }

    // Called at the deadline. The phase's limit is CPU time: on a loaded machine the worker
    // waits for a core, and the wait is not the student's. So while the phase has used less
    // CPU than its limit, the deadline moves to when it could have used it all, but never past
    // kLoadAllowance times the limit of wall-clock time (a worker that sleeps or blocks).
    bool phaseOverran() {
        const double limit = spec_.limits.wallSeconds;
        const Clock::time_point now = Clock::now();
        auto cpu = processCpuSeconds(pid_);
        if (!cpu || !cpuAtPhase_) return true;
        double used = *cpu - *cpuAtPhase_;
        Clock::time_point backstop = phaseRequestedAt_ + seconds(kLoadAllowance * limit);
        if (used >= limit || now >= backstop) return true;
        deadline_ = std::min(backstop, now + seconds(limit - used));
        return false;
    }

    void converse(int resultFd, int outputFd) {
        bool open[2] = {true, true};
        std::vector<uint8_t> buffer(1 << 16);
        while ((open[0] || open[1]) && !malformed() && !conversation_->done()) {
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now()).count();
            if (left <= 0) {
                if (!phaseOverran()) continue;
                overran_ = true;
                return;
            }
            pollfd fds[3] = {{open[0] ? resultFd : -1, POLLIN, 0},
                             {open[1] ? outputFd : -1, POLLIN, 0},
                             {!request_.empty() ? requestFd_ : -1, POLLOUT, 0}};
            int ready = poll(fds, 3, static_cast<int>(std::min<long long>(left, 1000)));
            if (ready < 0 && errno != EINTR) throw Error(std::string("grader: poll failed: ") + std::strerror(errno));
            if (ready <= 0) continue;
            if (fds[2].revents) writeRequest();
            for (int i = 0; i < 2; ++i) {
                if (!open[i] || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
                ssize_t n = read(fds[i].fd, buffer.data(), buffer.size());
                if (n < 0 && errno == EINTR) continue;
                if (n <= 0) {
                    open[i] = false;
                    continue;
                }
                if (i == 0) {
                    // Each verdict is answered before the records after it are read.
                    auto events = conversation_->feed(std::span(buffer.data(), size_t(n)));
                    while (!events.empty()) {
                        for (const WorkerEvent& event : events) handle(event);
                        events = conversation_->feed({});
                    }
                } else {
                    size_t room = kMaxCapturedOutput - std::min(kMaxCapturedOutput, run_.output.size());
                    run_.output.append(reinterpret_cast<const char*>(buffer.data()), std::min<size_t>(room, size_t(n)));
                }
            }
        }
    }

    void writeRequest() {
        if (!request_.writeTo(requestFd_)) {  // the worker closed its input
            close(requestFd_);
            requestFd_ = -1;
        }
    }

    void handle(const WorkerEvent& event) {
        if (event.kind != WorkerEvent::Kind::Verdict) return;
        size_t phase = event.phase;
        const std::vector<uint8_t>& payload = event.payload;
        PhaseOutcome& outcome = outcomes_[phase];
        const std::string stub = blame(phase);
        std::string text(payload.begin(), payload.end());
        if (event.droppedBytes > 0) text += " [" + std::to_string(event.droppedBytes) + " more bytes not shown]";
        switch (event.record) {
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
        case RecordKind::NotRun:
            outcome.status = PhaseStatus::Failed;
            outcome.reason = "not run: " + text;
            break;
        case RecordKind::OutOfMemory:
            outcome.status = PhaseStatus::OutOfMemory;
            outcome.reason = "exceeded the memory limit of " + std::to_string(spec_.limits.memoryMiB) + " MiB in " + stub;
            break;
        case RecordKind::Forbidden: {
            int32_t number = -1;
            if (payload.size() == sizeof number) std::memcpy(&number, payload.data(), sizeof number);
            outcome.status = PhaseStatus::Forbidden;
            outcome.reason = "made a forbidden system call (" + systemCallName(number) + ") in " + stub +
                             ": student code may not open files, start processes or use the network";
            break;
        }
        default: return;
        }
        finishPhase(phase);
        // A forbidden call ends the worker; every other verdict lets it go on.
        if (event.record != RecordKind::Forbidden) {
            conversation_->advance();
            queueRequest();
        }
    }

    // Before the worker has read phase 0, only code that runs at start-up can be running.
    std::string blame(size_t phase) const {
        if (phase == order_.front() && conversation_->step() == 0 && !conversation_->started())
            return "code that runs before any test (a global object's constructor or an initialiser)";
        return phases_[phase].stub;
    }

    // A phase's time runs from when the grader queued its request to the verdict: the worker is
    // the student's process, so nothing it sends (a PhaseStart record written early or late)
    // moves either end, and every CPU second it spends after one verdict is the next phase's.
    void finishPhase(size_t phase) {
        PhaseOutcome& outcome = outcomes_[phase];
        outcome.seconds = std::chrono::duration<double>(Clock::now() - phaseRequestedAt_).count();
        auto cpu = processCpuSeconds(pid_);
        if (cpu && cpuAtPhase_) outcome.cpuSeconds = *cpu - *cpuAtPhase_;
        reported_[phase] = true;
    }

    int reap() {
        int status = 0;
        while (!overran_ && !malformed()) {
            pid_t r = waitpid(pid_, &status, WNOHANG);
            if (r == pid_) return status;
            if (Clock::now() >= deadline_ && phaseOverran()) {
                overran_ = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        return status;
    }

    void judgeEnding(int status) {
        auto phase = conversation_->currentPhase();
        if (!phase || reported_[*phase]) return;
        PhaseOutcome& outcome = outcomes_[*phase];
        const std::string stub = blame(*phase);
        int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        if (malformed()) {
            outcome.status = PhaseStatus::Failed;
            outcome.reason = "sent malformed results from " + stub;
        } else if (overran_) {
            outcome.status = PhaseStatus::TimedOut;
            outcome.reason = "timed out after " + formatSeconds(spec_.limits.wallSeconds) + " s in " + stub;
        } else if (WIFSIGNALED(status)) {
            int sig = WTERMSIG(status);
            if (sig == SIGXCPU || sig == SIGKILL) {
                outcome.status = PhaseStatus::TimedOut;
                outcome.reason = "used more than " + std::to_string(spec_.limits.cpuSeconds) + " s of CPU time in " + stub;
            } else if (sig == SIGSYS) {
                outcome.status = PhaseStatus::Forbidden;
                outcome.reason = "made a forbidden system call in " + stub;
            } else {
                outcome.status = PhaseStatus::Crashed;
                outcome.reason = "crashed with " + signalName(sig) + " in " + stub;
            }
        } else if (code == worker::kExitSandboxFailed) {
            outcome.status = PhaseStatus::Failed;
            outcome.reason = "the worker " + spec_.path + " could not be started in its sandbox";
        } else {
            outcome.status = PhaseStatus::NoResults;
            outcome.reason = "the worker exited without results (" +
                             (code == worker::kExitCalled ? std::string("it called exit()") : "exit status " + std::to_string(code)) +
                             ") in " + stub;
        }
        finishPhase(*phase);
    }

    const WorkerSpec& spec_;
    std::span<const ChildPhase> phases_;
    SandboxRun& run_;
    std::vector<PhaseOutcome> outcomes_;
    std::vector<bool> reported_;
    std::vector<size_t> order_;
    std::optional<WorkerConversation> conversation_;
    RequestQueue request_;
    pid_t pid_ = -1;
    int requestFd_ = -1;
    Clock::time_point phaseRequestedAt_, deadline_;
    std::optional<double> cpuAtPhase_;  // the worker's CPU time when the current phase was requested
    bool overran_ = false;
};

}  // namespace

std::optional<PhaseOutcome> StubVerdicts::verdict(const ChildPhase& phase, const SandboxLimits& limits) const {
    if (unstarted_.count(phase.entry)) return PhaseOutcome{PhaseStatus::NotStarted, {}, "not started: " + phase.entry + " throws NotImplemented", 0.0, 0.0};
    auto it = timeouts_.find(phase.stub);
    if (it != timeouts_.end() && it->second >= kStrikes)
        return PhaseOutcome{PhaseStatus::TimedOut, {},
                            "not run: " + phase.stub + " already timed out " + std::to_string(kStrikes) + " times (limit " +
                                formatSeconds(limits.wallSeconds) + " s per test)",
                            0.0, 0.0};
    return std::nullopt;
}

std::vector<size_t> phasesToRun(std::span<const ChildPhase> phases, const StubVerdicts* known, const SandboxLimits& limits) {
    if (phases.empty()) return {};
    std::optional<PhaseOutcome> setup = known ? known->verdict(phases[0], limits) : std::nullopt;
    if (setup && setup->status != PhaseStatus::NotStarted) return {};
    std::vector<size_t> order = {0};
    for (size_t k = 1; k < phases.size(); ++k)
        if (!known || !known->verdict(phases[k], limits)) order.push_back(k);
    if (order.size() == 1 && (setup || phases[0].task == worker::kTaskNone)) return {};
    return order;
}

StartedWorker::StartedWorker(const WorkerSpec& worker, std::span<const ChildPhase> phases, std::vector<size_t> order)
    : order_(order.empty() ? allPhases(phases.size()) : std::move(order)), process_(spawnWorker(worker, phases, order_)) {}

StartedWorker::StartedWorker(StartedWorker&& other) noexcept : order_(std::move(other.order_)), process_(other.take()) {}

StartedWorker& StartedWorker::operator=(StartedWorker&& other) noexcept {
    if (this != &other) {
        stop();
        order_ = std::move(other.order_);
        process_ = other.take();
    }
    return *this;
}

void StartedWorker::stop() {
    if (process_.pid < 0) return;
    kill(process_.pid, SIGKILL);
    waitpid(process_.pid, nullptr, 0);
    for (int fd : {process_.requestFd, process_.resultFd, process_.outputFd}) close(fd);
    process_ = Process{};
}

StartedWorker::Process StartedWorker::take() { return std::exchange(process_, Process{}); }

SandboxRun runSandboxed(const WorkerSpec& worker, std::span<const ChildPhase> phases, StubVerdicts* known,
                        std::optional<StartedWorker> started) {
    // A worker that ends while the grader still writes its request must not end the grader.
    std::signal(SIGPIPE, SIG_IGN);
    SandboxRun run;
    run.phases.resize(phases.size());
    std::vector<bool> have(phases.size(), false), decided(phases.size(), false);
    for (size_t k = 0; k < phases.size() && known; ++k)
        if (auto verdict = known->verdict(phases[k], worker.limits)) {
            decided[k] = have[k] = true;
            run.phases[k] = std::move(*verdict);
        }
    std::vector<size_t> order = phasesToRun(phases, known, worker.limits);
    if (order.empty()) {
        // A set-up out of strikes: every phase shares its verdict. A set-up not started, as a
        // worker would: every later phase gives its own. An empty set-up completes with nothing.
        bool shareSetup = decided[0] && run.phases[0].status != PhaseStatus::NotStarted;
        for (size_t k = 1; k < phases.size() && shareSetup; ++k) run.phases[k] = run.phases[0];
        if (!decided[0]) run.phases[0] = PhaseOutcome{PhaseStatus::Completed, {}, {}, 0.0, 0.0};
        return run;
    }
    // A set-up not started runs anyway when later phases do: a worker goes on after it, and
    // gives their verdicts.
    if (decided[0]) have[0] = decided[0] = false;
    // A worker started for other phases allows inputs that will not be sent, or lacks room
    // for some that will: start one for these.
    if (started && started->order() != order) started.reset();
    while (true) {
        WorkerSession session(worker, phases, run);
        session.execute(order, std::exchange(started, std::nullopt));
        for (size_t k = 0; k < phases.size(); ++k)
            if (session.reported()[k] && !have[k]) {
                run.phases[k] = session.outcomes()[k];
                have[k] = true;
            }
        // Without the set-up nothing else can run: every phase shares its verdict.
        const PhaseOutcome& setup = session.reported()[0] ? session.outcomes()[0] : run.phases[0];
        if (setup.status != PhaseStatus::Completed) {
            for (size_t k = 1; k < phases.size(); ++k)
                if (!have[k]) {
                    run.phases[k] = PhaseOutcome{setup.status, {}, setup.reason, 0.0, 0.0};
                    have[k] = true;
                }
            break;
        }
        // A worker that ended early costs only its current phase: the next one repeats the
        // set-up and goes on with the first phase without a verdict.
        if (session.finished() || std::find(have.begin() + 1, have.end(), false) == have.end()) break;
        order = {0};
        for (size_t k = 1; k < phases.size(); ++k)
            if (!have[k]) order.push_back(k);
        // A worker that gave no new verdict at all cannot make progress: stop rather than loop.
        bool progressed = false;
        for (size_t k = 1; k < phases.size(); ++k) progressed |= session.reported()[k];
        if (!progressed) {
            for (size_t k = 1; k < phases.size(); ++k)
                if (!have[k]) {
                    run.phases[k] = PhaseOutcome{PhaseStatus::NoResults, {}, "the worker ended without results in " + phases[k].stub, 0.0, 0.0};
                    have[k] = true;
                }
            break;
        }
    }
    for (size_t k = 0; k < phases.size(); ++k) {
        if (!have[k]) run.phases[k] = PhaseOutcome{PhaseStatus::NoResults, {}, "the worker ended without results in " + phases[k].stub, 0.0, 0.0};
        // A phase that inherited the set-up's timeout did not time out itself.
        bool ownVerdict = k == 0 || run.phases[0].status == PhaseStatus::Completed;
        if (known && ownVerdict && !decided[k] && run.phases[k].status == PhaseStatus::TimedOut) known->recordTimeout(phases[k].stub);
    }
    return run;
}

std::string workerIsolation() {
    std::string isolation = "student code runs only in a separate, statically linked worker image holding no expected answers; "
                            "a seccomp filter loaded at its first instruction (no files, processes, network or signals to others); "
                            "CPU, memory, file-size and descriptor limits; wall-clock deadlines per phase";
    isolation += geteuid() == 0 ? "; the worker runs as the unprivileged user nobody" : "; the worker runs as the grader's own user";
    return isolation;
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
