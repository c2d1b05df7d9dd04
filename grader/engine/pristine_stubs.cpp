#include "grader/engine/pristine_stubs.h"

#include "framework/core/error.h"
#include "grader/engine/process_runner.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

constexpr const char* kGit = "/usr/bin/git";

std::string git(const std::string& sourceDir, std::vector<std::string> arguments) {
    std::vector<std::string> argv = {kGit, "-c", "safe.directory=" + sourceDir, "-C", sourceDir};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    ProcessLimits limits;
    limits.wallSeconds = 30;
    limits.outputBytes = size_t(16) << 20;
    ProcessResult r = runProcess(argv, {"PATH=/usr/bin", "HOME=/nonexistent", "GIT_CONFIG_NOSYSTEM=1"}, limits);
    if (!r.succeeded() || r.droppedBytes > 0)
        throw Error(sourceDir + ": cannot read the committed stubs with git (" + (r.failure.empty() ? "output too long" : r.failure) + ")");
    return r.output;
}

bool isStubSource(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    return extension == ".cpp" || extension == ".h";
}

}  // namespace

std::map<std::string, std::string> committedStubs(const std::string& sourceDir) {
    std::map<std::string, std::string> stubs;
    if (!fs::exists(fs::path(sourceDir) / ".git")) return stubs;
    // Two commands, not one per file: the names and sizes, then every file's contents in one
    // stream, cut by those sizes.
    std::istringstream tree(git(sourceDir, {"ls-tree", "-r", "-l", "HEAD", "--", "assignments/"}));
    std::vector<std::pair<std::string, size_t>> files;
    std::vector<std::string> show = {"show"};
    for (std::string line; std::getline(tree, line);) {
        size_t tab = line.find('\t');  // "<mode> blob <object> <size>\t<path>"
        std::istringstream fields(line.substr(0, tab));
        std::string mode, type, object;
        size_t size = 0;
        if (tab == std::string::npos || !(fields >> mode >> type >> object >> size) || type != "blob") continue;
        std::string name = line.substr(tab + 1);
        if (!isStubSource(name)) continue;
        files.emplace_back(name, size);
        show.push_back("HEAD:" + name);
    }
    if (files.empty()) return stubs;
    const std::string contents = git(sourceDir, show);
    size_t at = 0;
    for (const auto& [name, size] : files) {
        if (size > contents.size() - at) break;
        stubs[name] = contents.substr(at, size);
        at += size;
    }
    if (at != contents.size() || stubs.size() != files.size())
        throw Error(sourceDir + ": cannot read the committed stubs with git (their sizes and contents disagree)");
    return stubs;
}

std::map<std::string, std::string> pristineStubs(const std::string& sourceDir, const std::vector<std::string>& folders) {
    std::map<std::string, std::string> stubs = committedStubs(sourceDir);
    if (!fs::exists(fs::path(sourceDir) / ".git")) {
        fs::path root = fs::path(sourceDir) / "assignments";
        if (!fs::is_directory(root)) throw Error(root.string() + ": no stubs to grade against");
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            std::string name = entry.path().lexically_relative(sourceDir).string();
            if (!entry.is_regular_file() || !isStubSource(name)) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            stubs[name] = std::string(std::istreambuf_iterator<char>(in), {});
        }
    }
    if (stubs.empty()) throw Error(sourceDir + ": no committed stubs under assignments/");
    for (const std::string& folder : folders) {
        const std::string prefix = "assignments/" + folder + "/";
        auto first = stubs.lower_bound(prefix);
        if (first == stubs.end() || first->first.compare(0, prefix.size(), prefix) != 0)
            throw Error(sourceDir + ": " + prefix + " has no committed stub; submissions are built against the stubs at git's HEAD, so commit it first");
    }
    return stubs;
}

}  // namespace rtlab::grader
