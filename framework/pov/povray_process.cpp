#include "framework/pov/povray_process.h"

#include "framework/core/error.h"

#include <fcntl.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <fstream>

extern char** environ;

namespace rtlab {
namespace fs = std::filesystem;

TemporaryDirectory::TemporaryDirectory(const std::string& prefix) {
    std::string pattern = (fs::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
        throw Error("cannot create a temporary folder " + pattern + ": " + std::strerror(errno));
    path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
    if (keep_) return;
    std::error_code ignored;  // a destructor must not throw; a leftover temp folder is harmless
    fs::remove_all(path_, ignored);
}

int runPovray(const std::vector<std::string>& arguments, const fs::path& workDir, const fs::path& logPath) {
    std::vector<std::string> argvStrings{"povray"};
    argvStrings.insert(argvStrings.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& s : argvStrings) argv.push_back(s.data());
    argv.push_back(nullptr);

    // posix_spawn rather than fork: safe in a multi-threaded process.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, workDir.c_str());
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, fs::absolute(logPath).c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = 0;
    int spawnError = posix_spawnp(&pid, "povray", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawnError != 0)
        throw Error(std::string("cannot start povray: ") + std::strerror(spawnError) +
                    " (install it with scripts/install-deps)");
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw Error(std::string("waiting for povray: ") + std::strerror(errno));
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

namespace {

// POV-Ray's first line that says what went wrong, to quote in a one-line error.
std::string firstErrorLine(const fs::path& logPath) {
    std::ifstream in(logPath);
    std::string line;
    while (std::getline(in, line)) {
        bool isError = line.find("Error") != std::string::npos || line.find("error") != std::string::npos;
        if (isError && line.find("user configuration file") == std::string::npos) return line;
    }
    return "";
}

}  // namespace

void runPovrayOrThrow(const std::vector<std::string>& arguments, TemporaryDirectory& work,
                      const std::string& what) {
    fs::path logPath = work.path() / "povray.log";
    int status = runPovray(arguments, work.path(), logPath);
    if (status == 0) return;
    work.keep();
    std::string reason = firstErrorLine(logPath);
    throw Error("povray failed (exit " + std::to_string(status) + ") " + what +
                (reason.empty() ? "" : ": " + reason) + "; log: " + logPath.string());
}

std::string povrayVersion() {
    // Asked once per process: the installed POV-Ray does not change while we run.
    static const std::string version = [] {
        TemporaryDirectory work("rtlab-povray-version");
        fs::path logPath = work.path() / "version.txt";
        runPovray({"--version"}, work.path(), logPath);
        std::ifstream in(logPath);
        std::string line;
        while (std::getline(in, line))
            if (line.rfind("POV-Ray ", 0) == 0) return line;
        throw Error("povray --version printed no 'POV-Ray <version>' line");
    }();
    return version;
}

}  // namespace rtlab
