// Builds a student's submission into its own rtlab executable (docs/grading.md, "Grading a
// submission"): the student's assignment files, with the repository's stubs for any file the
// submission lacks, are compiled with the flags of the build tree and linked against the
// libraries already built there. Student code must not run outside the sandbox: constructors
// of global objects are removed from student objects (with a note) and ifunc resolvers are
// refused. Framework libraries are linked whole and first, so a student file that defines a
// framework function fails to link instead of replacing it.
#pragma once

#include <string>
#include <vector>

namespace rtlab::grader {

struct SubmissionBuild {
    bool succeeded = false;
    std::string executable;
    std::string log;                      // compiler and linker messages, or why the build was refused
    std::vector<std::string> fromSubmission;  // the files taken from the submission
};

// toolchainPath: build/grader/submission-toolchain.json; workDir: an empty directory.
SubmissionBuild buildSubmission(const std::string& submissionDir, const std::string& sourceDir,
                                const std::string& toolchainPath, const std::string& workDir);

}  // namespace rtlab::grader
