// Runs student code in forked children (docs/grading.md, "Isolation"). The parent has loaded
// the scene and prepared the inputs; each child sets a CPU-time and an address-space limit,
// installs the system-call filter, then runs the phases of one test group and sends their raw
// results over a pipe. The parent enforces a wall-clock limit per phase, turns every way a
// child can end into a one-line verdict, and never runs student code itself.
#pragma once

#include "grader/wire_format.h"

#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace rtlab::grader {

struct SandboxLimits {
    double wallSeconds = 5.0;  // per phase
    int cpuSeconds = 30;        // per child, all threads together
    int memoryMiB = 512;        // on top of what the grader itself has mapped
};

// One step of a child's work. It calls student code (stub names it in verdicts) and writes
// raw results only: hits, structures, values. Phase 0 of a group is the set-up the others
// need (typically the build); it runs in every child of the group.
struct ChildPhase {
    std::string stub;  // e.g. "a1 buildBvh (assignments/a1_bvh/bvh_build.cpp)"
    std::function<void(ByteWriter&)> run;
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
    double seconds = 0.0;
};

struct SandboxRun {
    std::vector<PhaseOutcome> phases;
    std::string output;  // what the student code printed (first few KiB)
};

// Counts wall-clock timeouts per stub across a grading run, so a stub that hangs on every
// input costs its time limit twice, not once per test.
class TimeoutStrikes {
public:
    static constexpr int kLimit = 2;
    bool exhausted(const std::string& stub) const;
    void record(const std::string& stub) { ++counts_[stub]; }

private:
    std::map<std::string, int> counts_;
};

// Runs every phase. When a child dies in phase k > 0, a new child runs the set-up again and
// continues with phase k + 1, so one crash costs only the tests that depend on that phase.
// Phases whose stub has exhausted its strikes are reported as timed out without running.
SandboxRun runSandboxed(std::span<const ChildPhase> phases, const SandboxLimits& limits, TimeoutStrikes* strikes = nullptr);

const char* phaseStatusName(PhaseStatus status);

}  // namespace rtlab::grader
