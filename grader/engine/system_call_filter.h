// The seccomp filter a worker runs under (docs/grading.md, "Isolation and trust"): computing,
// allocating memory, threads of its own process, reading its request and writing to the
// result pipe and the output capture are allowed; opening files, sockets, starting processes
// or programs, signalling other processes and tracing are not. The grader builds it; the
// worker's entry point loads it before any other instruction (grader/worker/sandbox_entry.cpp).
#pragma once

#include <string>

namespace rtlab::grader {

// Writes the filter as a raw BPF program to a new memory file and returns its descriptor,
// positioned at the start. A forbidden call raises SIGSYS; writes are allowed only to stdout,
// stderr and resultFd; signals only to workerPid. Throws std::runtime_error on failure.
int exportSystemCallFilter(int resultFd, int workerPid);

// The name of a system call number on this architecture ("openat"), for verdicts.
std::string systemCallName(int number);

}  // namespace rtlab::grader
