// rtlab release DIR (docs/grading.md, "A student release"): writes the repository a course
// publishes to its students. It is made from the committed files of the repository this
// executable was built from (git archive HEAD, never the working tree, so nothing half-edited
// or private ships), minus everything that holds an answer or needs one, and becomes a fresh
// git repository with a single commit.
#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/pov/povray_process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
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

struct ReleaseFlags {
    std::string dir;
    std::string repository = RTLAB_REPOSITORY_DIR;
};

std::string firstLine(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

// Runs program with stdin closed, stdout into `out` and stderr into `err`; throws rtlab::Error
// naming `what` and the program's first error line when it fails.
void run(const std::vector<std::string>& command, const fs::path& out, const fs::path& err, const std::string& what) {
    std::vector<std::string> args = command;
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    // posix_spawn rather than fork: safe in a multi-threaded process.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    int spawnError = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawnError != 0) throw Error("release: cannot run " + command[0] + " (is it installed?)");
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::string line = firstLine(err);
        throw Error("release: " + what + " failed" + (line.empty() ? "" : ": " + line));
    }
}

// Runs command in scratch and returns the first line it printed.
std::string outputOf(const std::vector<std::string>& command, const TemporaryDirectory& scratch, const std::string& what) {
    run(command, scratch.path() / "stdout", scratch.path() / "stderr", what);
    return firstLine(scratch.path() / "stdout");
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
    fs::path out = scratch.path() / "stdout", err = scratch.path() / "stderr";
    std::string repository = fs::weakly_canonical(fs::absolute(flags.repository)).string();
    std::string commit, top;
    try {
        top = outputOf({"git", "-C", repository, "rev-parse", "--show-toplevel"}, scratch, "");
        commit = outputOf({"git", "-C", repository, "rev-parse", "--verify", "HEAD^{commit}"}, scratch, "");
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
    std::vector<std::string> archive{"git", "-C", repository, "archive", "--format=tar", "--output=" + tarball.string(),
                                     commit, "--", "."};
    for (const LeftOut& left : kLeftOut) archive.push_back(std::string(":(exclude)") + left.path);
    run(archive, out, err, "git archive of " + repository);
    run({"tar", "-xf", tarball.string(), "-C", dir.string()}, out, err, "unpacking the archive into " + dir.string());

    std::string d = dir.string();
    run({"git", "init", "--quiet", "--initial-branch=main", d}, out, err, "git init in " + d);
    run({"git", "-C", d, "add", "--all"}, out, err, "git add in " + d);
    // The user's identity if git has one, else a neutral one, so the commit never fails for
    // want of a name.
    std::vector<std::string> commitCommand{"git", "-C", d};
    try {
        outputOf({"git", "-C", d, "config", "user.email"}, scratch, "");
    } catch (const Error&) {
        commitCommand.insert(commitCommand.end(), {"-c", "user.name=rtlab release", "-c", "user.email=rtlab@localhost"});
    }
    std::string shortCommit = commit.substr(0, 12);
    commitCommand.insert(commitCommand.end(), {"commit", "--quiet", "-m", "Student release of rtlab (from " + shortCommit + ")"});
    run(commitCommand, out, err, "git commit in " + d);
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
