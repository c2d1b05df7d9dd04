// Runs student code in worker processes (docs/grading.md, "Isolation and trust"). A worker is
// a fresh, statically linked image (grader/worker/) that holds the student's code and none of
// the grader's answers; it loads the grader's system-call filter at its first instruction and
// runs with CPU, memory and file limits, as an unprivileged user when the grader is root. The
// grader streams it one phase at a time, reads raw results with bounds checks, enforces wall-
// clock deadlines that nothing the worker sends can extend, turns every way a worker can end
// into a one-line verdict, and never runs student code itself.
#pragma once

#include "grader/wire/wire_format.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <sys/types.h>

namespace rtlab::grader {

struct SandboxLimits {
    double wallSeconds = 5.0;  // per phase: CPU seconds, and at most 4 times that of wall clock (sandbox.cpp)
    int cpuSeconds = 30;        // per worker, all threads together
    int memoryMiB = 512;        // address space of a worker beyond its inputs
};

// The executable that runs the student's code (rtlab-worker, rtlab-worker-solution, or the
// one built from a submission) and its limits.
struct WorkerSpec {
    std::string path;
    SandboxLimits limits;
};

// One step of a worker's work: a task of grader/wire/task_inputs.h with its input. It calls
// student code (stub names it in verdicts) and returns raw results only: hits, structures,
// values. Phase 0 of a group is the set-up the others need (typically the build); it runs in
// every worker of the group.
struct ChildPhase {
    std::string stub;  // e.g. "a1 buildBvh (assignments/a1_bvh/bvh_build.cpp)"
    std::string task;
    std::vector<uint8_t> input;
    // The stub the task calls first on every input, as it names itself in NotImplemented: stub
    // itself when that names one function, one of them when it names several, empty when the
    // task may end without calling any (a query with no rays to ask). A committed entry decides
    // the phase's verdict without running it (StubVerdicts).
    std::string entry;
};

enum class PhaseStatus {
    Completed,    // data holds the raw results
    NotStarted,   // a stub threw rtlab::NotImplemented
    Failed,       // threw an exception, or sent malformed results
    Crashed,      // killed by a signal
    TimedOut,     // wall-clock or CPU limit
    OutOfMemory,  // std::bad_alloc under the address-space limit
    Forbidden,    // tried a system call the filter blocks
    NoResults,    // the child exited before reporting this phase
};

struct PhaseOutcome {
    PhaseStatus status = PhaseStatus::NoResults;
    std::vector<uint8_t> data;
    std::string reason;  // one line, for anything but Completed
    double seconds = 0.0;     // wall clock, from the request to the verdict
    double cpuSeconds = 0.0;  // the worker's CPU time (all threads) while the phase ran, as the kernel counted it
};

struct SandboxRun {
    std::vector<PhaseOutcome> phases;
    std::string output;  // raw bytes the student code printed (first few KiB); escape before showing
};

// What a grading run knows of a phase's stub before it runs, given as the phase's verdict
// without running it:
//  - a stub the worker holds exactly as committed (worker_sources.h) is not started: every
//    committed stub throws NotImplemented on entry, whatever its input;
//  - a stub that timed out kStrikes times is reported timed out, so a stub that hangs on every
//    input costs its time limit twice, not once per test.
class StubVerdicts {
public:
    static constexpr int kStrikes = 2;
    // unstarted: the stubs (StubTable::name) whose file the worker holds as committed.
    explicit StubVerdicts(std::set<std::string> unstarted = {}) : unstarted_(std::move(unstarted)) {}
    std::optional<PhaseOutcome> verdict(const ChildPhase& phase, const SandboxLimits& limits) const;
    void recordTimeout(const std::string& stub) { ++timeouts_[stub]; }

private:
    std::set<std::string> unstarted_;
    std::map<std::string, int> timeouts_;
};

// The phases a worker has to run: phase 0 and every later phase without a verdict from
// `known`. None when phase 0 has a verdict (every phase shares it), or when phase 0 is the
// empty set-up (noSetUp, test_group.h) and every later phase has one.
std::vector<size_t> phasesToRun(std::span<const ChildPhase> phases, const StubVerdicts* known, const SandboxLimits& limits);

// A worker started before its phases are requested: sandboxed, it waits for its first request.
// The grading session starts the next group's worker while the current group runs, so that a
// group pays no start-up before its first verdict. The set-up phase's CPU time (and its CPU
// limit) still counts from the worker's start, so work done while waiting is the set-up's;
// only its wall clock starts at the request. Dropped unused, the worker is killed.
class StartedWorker {
public:
    // Started for `order` (phasesToRun), whose inputs its address space allows; for every phase
    // when none is given.
    StartedWorker(const WorkerSpec& worker, std::span<const ChildPhase> phases, std::vector<size_t> order = {});
    StartedWorker(StartedWorker&& other) noexcept;
    StartedWorker& operator=(StartedWorker&& other) noexcept;
    ~StartedWorker() { stop(); }

    struct Process {
        pid_t pid = -1;
        int requestFd = -1, resultFd = -1, outputFd = -1;  // the grader's ends of the worker's pipes
    };
    // Hands the process over; the caller closes the descriptors and reaps it.
    Process take();
    const std::vector<size_t>& order() const { return order_; }

private:
    void stop();  // kills and reaps a worker not handed over
    std::vector<size_t> order_;
    Process process_;
};

// Runs every phase. When a child dies in phase k > 0, a new child runs the set-up again and
// continues with phase k + 1, so one crash costs only the tests that depend on that phase.
// Phases `known` has a verdict for are not run, and a phase that times out is recorded in it.
// `started`, when given, is a worker started for these phases; it runs the first session if
// it was started for the phases that run.
SandboxRun runSandboxed(const WorkerSpec& worker, std::span<const ChildPhase> phases, StubVerdicts* known = nullptr,
                        std::optional<StartedWorker> started = std::nullopt);

// What the worker's isolation consists of on this machine, for the reports.
std::string workerIsolation();

const char* phaseStatusName(PhaseStatus status);

}  // namespace rtlab::grader
