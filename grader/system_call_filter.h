// The seccomp filter every sandboxed child installs before it runs student code
// (docs/grading.md, "Isolation"): computing, allocating memory, threads of its own process and
// writing to the result pipe and the output capture are allowed; opening files, sockets,
// starting processes or programs, signalling other processes and tracing are not.
#pragma once

#include <string>

namespace rtlab::grader {

// Installs the filter on the calling process. A forbidden call raises SIGSYS (the child's
// handler reports it); writes are allowed only to stdout, stderr and resultFd. Throws
// std::runtime_error if the kernel refuses the filter.
void installSystemCallFilter(int resultFd);

// The name of a system call number on this architecture ("openat"), for verdicts.
std::string systemCallName(int number);

}  // namespace rtlab::grader
