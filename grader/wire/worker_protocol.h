// The conversation between the grader and a worker (docs/grading.md, "Isolation and trust").
// The worker is a separate, statically linked executable that holds the student's code and
// nothing else the grader knows: no expected answers, no reference data. The grader streams it
// one phase at a time on its standard input and reads raw results from kResultFd; everything
// the worker says is validated by the grader, which alone computes scores.
//
// Request (grader -> worker, fd 0), repeated:  u32 phase, u32 task-name length, name,
//                                              u64 input length, input bytes
//                                        end:  u32 kEndOfRequest
// The grader sends phase k+1 only after phase k's verdict, so no input is in the worker's
// memory before the phase that needs it (a build cannot look at the rays it will be asked).
//
// Record (worker -> grader, kResultFd): u8 kind, u32 phase, u64 payload length, payload.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rtlab::grader::worker {

inline constexpr int kResultFd = 3;  // records to the grader
inline constexpr int kFilterFd = 4;  // the seccomp program, read once by the entry point

inline constexpr uint32_t kEndOfRequest = 0xffffffffu;
inline constexpr uint32_t kMaxTaskName = 64;

enum class RecordKind : uint8_t {
    PhaseStart = 1,  // the phase's input is read; student code runs from here
    PhaseData,       // the phase completed; payload = raw results
    NotStarted,      // a stub threw NotImplemented; payload = its name
    Failed,          // an exception; payload = its message
    OutOfMemory,     // std::bad_alloc
    Forbidden,       // the filter trapped a system call; payload = its number (i32)
    Done,            // every phase of the request ran
    NotRun,          // the task would not call student code on what an earlier phase made; payload = why
};
inline constexpr uint8_t kFirstRecordKind = uint8_t(RecordKind::PhaseStart);
inline constexpr uint8_t kLastRecordKind = uint8_t(RecordKind::NotRun);
inline constexpr size_t kRecordHeaderSize = 1 + 4 + 8;

// Exit statuses the framework's part of the worker uses; anything else is the student's.
inline constexpr int kExitSandboxFailed = 121;  // the entry point could not install the filter
inline constexpr int kExitBadRequest = 122;     // the request did not parse
inline constexpr int kExitForbidden = 125;      // after reporting a forbidden system call
inline constexpr int kExitCalled = 86;          // student code called exit()

}  // namespace rtlab::grader::worker
