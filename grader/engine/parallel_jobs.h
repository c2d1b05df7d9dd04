// Independent jobs of a grading run (the submission's files, the stubs' objects), each a
// compiler in its own sandbox, run a few at a time: the machine's cores are then busy while
// one compiler waits on its files.
#pragma once

#include <cstddef>
#include <functional>

namespace rtlab::grader {

// How many compilers a grading run keeps busy at once: the machine's hardware threads, at most
// four (a batch engine runs several gradings side by side).
size_t compileThreads();

// Calls job(0) to job(count - 1), each once, on up to `threads` threads, the calling one among
// them, and returns when all have returned. A job must not throw.
void runInParallel(size_t count, size_t threads, const std::function<void(size_t)>& job);

}  // namespace rtlab::grader
