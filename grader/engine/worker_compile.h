// Compiling a merged submission (submission_build.h) into its worker, in the compile sandbox:
// each source on its own, as many at once as the machine has cores, then one link. On two cores
// that halves the compile of a seven-assignment submission, the largest part of grading one. One
// deadline covers every process, as it covered the single command this replaces.
#pragma once

#include "grader/engine/compile_sandbox.h"

#include <nlohmann/json.hpp>

#include <string>

namespace rtlab::grader {

struct WorkerCompile {
    bool succeeded = false;
    bool timedOut = false;
    std::string log;         // the compiler's output, sources in path order, capped as one process's
    size_t droppedBytes = 0;
    std::string failure;     // why the compiler could not run, when it printed nothing
    size_t sources = 0;      // the .cpp files
    size_t cached = 0;       // of those, objects copied from the cache, not compiled
};

// Compiles every .cpp under host.sources with the toolchain's compile flags and links the
// objects with everything in host.objects into host.output/rtlab-worker. Each .cpp compiles in
// a view of its own beside host.sources (units/N/: the submission's headers and that file, no
// other .cpp), so its object is kept in cacheDir (unit_object_cache.h) and a later grading
// with the same bytes copies it instead of compiling; empty cacheDir: nothing is kept.
WorkerCompile compileWorker(const CompileSandbox& sandbox, const CompileInputs& host, const nlohmann::json& toolchain,
                            const ProcessLimits& limits, const std::string& cacheDir);

}  // namespace rtlab::grader
