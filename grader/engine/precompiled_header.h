// The student headers of the framework compiled once into a GCC precompiled header, kept by
// content like the stubs' object (stub_object_cache.h). A submission file spends most of its
// compile in those headers (GLM and the standard library behind them): with the header
// precompiled, each file compiles in about half the time (docs/grading.md, "Grading a
// submission").
//
// Each file then compiles as if it began with the assignment interfaces (`-include`, as CMake's
// precompiled headers do). A file that compiles alone but not after them (a name of its own that
// clashes with one of theirs) is compiled again without, so that nothing a student wrote fails
// for it (worker_compile.cpp).
#pragma once

#include "grader/engine/compile_sandbox.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rtlab::grader {

// The header every file of a submission is compiled after, inside CompileInputs::precompiled.
inline constexpr const char* kPrecompiledHeaderName = "rtlab_student_headers.h";

struct PrecompiledHeaderRequest {
    std::string headersDir;  // the student headers (copied by the grader, never the submission's)
    nlohmann::json toolchain;
    std::string cacheDir;  // where compiled headers are kept, one folder per key
    std::string workDir;   // an empty folder for this compile
    ProcessLimits limits;
};

// A folder holding kPrecompiledHeaderName and its .gch, from the cache when the same headers and
// toolchain were compiled before. Empty, with *why (one line), when it cannot be made: files then
// compile without it.
std::string precompiledHeaderDir(const PrecompiledHeaderRequest& request, std::string* why);

// The flags that compile a file after the header, for a compile that sees the paths `seen`
// (CompileSandbox::visiblePaths); none when it has no precompiled header.
std::vector<std::string> precompiledHeaderFlags(const CompileInputs& seen);

}  // namespace rtlab::grader
