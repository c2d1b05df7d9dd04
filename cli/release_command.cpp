// rtlab release DIR (docs/grading.md, "A student release"): writes the repository a course
// publishes to its students. It is made from the committed files of the repository this
// executable was built from (git archive HEAD, never the working tree, so nothing half-edited
// or private ships), minus everything that holds an answer or needs one, and becomes a fresh
// git repository with a single commit.
#include "cli/commands.h"
#include "cli/this_build.h"
#include "framework/core/error.h"
#include "framework/external/temporary_directory.h"
#include "grader/engine/process_runner.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

extern char** environ;

namespace rtlab::cli {
namespace {

namespace fs = std::filesystem;

// What a student release leaves out, and why. The Gradescope zip is a release too
// (scripts/make-gradescope), so this is the one list of what never reaches students.
struct LeftOut {
    const char* path;
    const char* why;
};
constexpr LeftOut kLeftOut[] = {
    {"solutions", "the reference implementation"},
    {"fast", "the tuned wide BVH, with a0's answer inside"},
    {"grader/fixtures", "the instructors' hostile submissions and their verdicts"},
    {"bench", "benchmarks of the reference solutions and the fast paths"},
    {"tests", "the framework's own suite, which runs on the reference solutions"},
    {".ci", "CI of the full repository, which runs all of the above"},
};

// Absolute paths, as runProcess wants them: Debian's.
constexpr const char* kGit = "/usr/bin/git";
constexpr const char* kTar = "/usr/bin/tar";

struct ReleaseFlags {
    std::string dir;
    std::string repository = repositoryDir();
};

// Runs a program with stdin closed, this process's environment (git needs HOME for the user's
// identity) and a generous wall-clock cap; returns the first line it printed, and throws
// rtlab::Error naming `what` and that line when it fails.
std::string run(const std::vector<std::string>& command, const std::string& what) {
    std::vector<std::string> environment;
    for (char** variable = environ; *variable; ++variable) environment.emplace_back(*variable);
    grader::ProcessLimits limits;
    limits.wallSeconds = 600;
    limits.cpuSeconds = 600;
    grader::ProcessResult result = grader::runProcess(command, environment, limits);
    std::string line = result.output.substr(0, result.output.find('\n'));
    if (!result.succeeded())
        throw Error("release: " + what + " failed" + (line.empty() ? ": " + result.failure : ": " + line));
    return line;
}

// Removes a release that failed half-way, so the folder is as the user left it: absent or empty.
struct RemoveUnlessDone {
    fs::path dir;
    bool existed;
    bool done = false;
    ~RemoveUnlessDone() {
        if (done) return;
        std::error_code ignored;
        if (existed)
            for (const fs::directory_entry& entry : fs::directory_iterator(dir, ignored)) fs::remove_all(entry.path(), ignored);
        else
            fs::remove_all(dir, ignored);
    }
};

void release(const ReleaseFlags& flags) {
    fs::path dir = fs::absolute(flags.dir).lexically_normal();
    std::error_code error;
    bool existed = fs::exists(dir, error);
    if (existed && !fs::is_directory(dir))
        throw Error("release: " + dir.string() + " exists and is not a folder; choose a new folder");
    if (existed && !fs::is_empty(dir, error))
        throw Error("release: " + dir.string() + (error ? " cannot be read: " + error.message() : " is not empty") +
                    "; choose a new or empty folder");
    TemporaryDirectory scratch("rtlab-release");
    std::string repository = fs::weakly_canonical(fs::absolute(flags.repository)).string();
    std::string commit, top;
    try {
        top = run({kGit, "-C", repository, "rev-parse", "--show-toplevel"}, "git rev-parse");
        commit = run({kGit, "-C", repository, "rev-parse", "--verify", "HEAD^{commit}"}, "git rev-parse");
    } catch (const Error&) {
        throw Error("release: " + repository + " is not a git repository with a commit (see --from)");
    }
    // A folder inside a repository would release only that folder's files.
    if (fs::weakly_canonical(top) != repository)
        throw Error("release: " + repository + " is inside the git repository " + top + ", not its top folder (see --from)");

    fs::create_directories(dir, error);
    if (error) throw Error("release: cannot create " + dir.string() + ": " + error.message());
    RemoveUnlessDone cleanup{dir, existed};

    fs::path tarball = scratch.path() / "release.tar";
    std::vector<std::string> archive{kGit, "-C", repository, "archive", "--format=tar", "--output=" + tarball.string(),
                                     commit, "--", "."};
    for (const LeftOut& left : kLeftOut) archive.push_back(std::string(":(exclude)") + left.path);
    run(archive, "git archive of " + repository);
    run({kTar, "-xf", tarball.string(), "-C", dir.string()}, "unpacking the archive into " + dir.string());

    std::string d = dir.string();
    run({kGit, "init", "--quiet", "--initial-branch=main", d}, "git init in " + d);
    run({kGit, "-C", d, "add", "--all"}, "git add in " + d);
    // The user's identity if git has one, else a neutral one, so the commit never fails for
    // want of a name.
    std::vector<std::string> commitCommand{kGit, "-C", d};
    try {
        run({kGit, "-C", d, "config", "user.email"}, "git config");
    } catch (const Error&) {
        commitCommand.insert(commitCommand.end(), {"-c", "user.name=rtlab release", "-c", "user.email=rtlab@localhost"});
    }
    std::string shortCommit = commit.substr(0, 12);
    commitCommand.insert(commitCommand.end(), {"commit", "--quiet", "-m", "Student release of rtlab (from " + shortCommit + ")"});
    run(commitCommand, "git commit in " + d);
    cleanup.done = true;

    size_t files = 0;
    for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
        if (it->path().filename() == ".git") it.disable_recursion_pending();
        else if (it->is_regular_file()) ++files;
    }
    std::cout << "wrote a student release of " << repository << " at " << shortCommit << " to " << d << " (" << files
              << " files, one commit); left out:";
    for (const LeftOut& left : kLeftOut) std::cout << " " << left.path << "/";
    std::cout << "\n";
}

}  // namespace

void addReleaseCommand(CLI::App& app) {
    auto flags = std::make_shared<ReleaseFlags>();
    std::string description =
        "Write a student release: the files committed at HEAD, as a new git repository with one commit "
        "(docs/grading.md), without";
    for (const LeftOut& left : kLeftOut) description += std::string(" ") + left.path + "/ (" + left.why + "),";
    description.back() = '.';
    CLI::App* command = app.add_subcommand("release", description);
    command->add_option("dir", flags->dir, "Folder to create (must be absent or empty)")->required();
    command->add_option("--from", flags->repository, "Git repository whose HEAD is released (default: the one rtlab was built from)")
        ->capture_default_str();
    command->callback([flags] { release(*flags); });
}

}  // namespace rtlab::cli
