// Where a submission is compiled (docs/grading.md, "Isolation and trust"). The compiler sees
// the student's files, the headers students are meant to include, the system headers and
// toolchain, the objects it links against (the worker runtime, the committed stubs of the
// assignments not graded), the student headers precompiled, and a folder for its output;
// nothing else:
// not solutions/, not the grader's data, not scenes/refs/, not the rest of the machine. Under
// bubblewrap that is a fresh mount namespace holding only those paths (and no network, no
// other processes); where the machine allows no namespaces, the compiler runs as the
// unprivileged user nobody on the real file system, and the reports say so.
#pragma once

#include "grader/engine/process_runner.h"

#include <string>
#include <vector>

namespace rtlab::grader {

// The host folders and files the compiler may see, and where it sees them.
struct CompileInputs {
    std::string sources;  // the submission merged over the stubs: assignments/...
    std::string headers;  // framework/... headers meant for students
    std::string objects;  // a folder of objects to link: the worker runtime, compiled stubs
    std::string output;   // a writable, empty folder
    std::string precompiled;  // the student headers precompiled (precompiled_header.h); empty: none
};

class CompileSandbox {
public:
    // Probes once whether bubblewrap can make namespaces here.
    static const CompileSandbox& detect();

    bool usesNamespaces() const { return bubblewrap_; }
    std::string description() const;

    // The paths as the compiler sees them.
    CompileInputs visiblePaths(const CompileInputs& host) const;
    // Runs command (written with visiblePaths) in the sandbox with limits.
    ProcessResult run(const CompileInputs& host, const std::vector<std::string>& command, ProcessLimits limits) const;

private:
    bool bubblewrap_ = false;
    std::string whyNot_;
};

}  // namespace rtlab::grader
