// Builds a student's submission into a worker of its own (docs/grading.md, "Grading a
// submission"): the student's assignment files, over the committed stubs for any file the
// submission lacks, are compiled inside the compile sandbox (compile_sandbox.h) and linked
// statically with the worker runtime, as rtlab-worker is. Nothing is taken from the working
// tree's compiled objects.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rtlab::grader {

struct SubmissionBuild {
    bool succeeded = false;
    std::string executable;                   // the worker
    std::string log;                          // raw compiler and linker output, or why the build was refused
    std::vector<std::string> fromSubmission;  // the files taken from the submission
    size_t sources = 0, cached = 0;           // .cpp files, and those whose objects came from the cache
    // One line for each piece of committed code (the student headers, the stubs) that could not
    // be had compiled once: the build still succeeds, only slower, and this says why.
    std::vector<std::string> slower;
};

struct CompileLimits {
    double wallSeconds = 120.0;
    int memoryMiB = 4096;
};

// stubs: the committed stubs (pristine_stubs.h), for the files the submission lacks.
// toolchainPath: build/grader/submission-toolchain.json; workDir: an empty directory.
// gradedFolders: the assignments/ folders the graded tests call, taken from the submission; the
// others link their committed stubs, compiled once (stub_object_cache.h); empty: every folder
// from the submission. Throws rtlab::Error with one line when the submission cannot be read
// (a symbolic link, an unreadable or oversized file).
SubmissionBuild buildSubmission(const std::string& submissionDir, const std::string& sourceDir, std::map<std::string, std::string> stubs,
                                const std::string& toolchainPath, const std::string& workDir, const CompileLimits& limits = {},
                                const std::vector<std::string>& gradedFolders = {});

}  // namespace rtlab::grader
