// The committed stubs of an assignment a grading run does not grade, compiled once into one
// relocatable object per assignment folder and kept by content (docs/grading.md, "Grading a
// submission"). Grading one assignment then compiles only that assignment's files of the
// submission (and those it builds on), so a submission's compile time does not grow with the
// number of assignments in the course, and each folder's stubs compile once whichever others
// a run grades. The object holds committed files only, never a student's, and is compiled in
// the same sandbox as a submission.
#pragma once

#include "grader/engine/compile_sandbox.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace rtlab::grader {

// The time limit of the stubs' compile (wall and CPU seconds): generous, because it runs once
// per cache key and its input is the repository's own code.
inline constexpr double kStubCompileSeconds = 600.0;

struct StubObjectRequest {
    std::map<std::string, std::string> stubs;  // repository path -> contents
    std::string headersDir;                    // the student headers the stubs include
    nlohmann::json toolchain;                  // build/grader/submission-toolchain.json
    std::string cacheDir;                      // where compiled objects are kept
    std::string workDir;                       // an empty folder for this compile
    ProcessLimits limits;
    std::string precompiledDir;                // the student headers precompiled; empty: none
};

// The path of an object with every stub of the request compiled, from the cache when the same
// stubs, headers and toolchain were compiled before. Empty, with *why (one line), when it cannot
// be made: the caller then compiles the stubs with the submission.
std::string compiledStubObject(const StubObjectRequest& request, std::string* why);

}  // namespace rtlab::grader
