#include "grader/engine/precompiled_header.h"

#include "grader/engine/cache_files.h"
#include "grader/engine/compiler_messages.h"
#include "grader/engine/submission_toolchain.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <vector>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// The header's text: each assignment's interface (framework/interface/aN_*.h, so that a new
// assignment's is in without a change here) and the error type every stub includes.
std::string headerText(const fs::path& headersDir) {
    std::vector<std::string> interfaces;
    for (const auto& entry : fs::directory_iterator(headersDir / "framework/interface")) {
        const std::string name = entry.path().filename().string();
        if (name.size() > 3 && name[0] == 'a' && std::isdigit(static_cast<unsigned char>(name[1])) && entry.path().extension() == ".h")
            interfaces.push_back(name);
    }
    std::sort(interfaces.begin(), interfaces.end());
    std::string text = "// Compiled by rtlab-grader into a precompiled header; see grader/engine/precompiled_header.h.\n";
    text += "#include \"framework/core/error.h\"\n";
    for (const std::string& name : interfaces) text += "#include \"framework/interface/" + name + "\"\n";
    return text;
}

// Removes every kept header but `kept`: each is about 60 MiB, and one made from older headers
// is not used again. A grading still compiling with one it removes compiles its files
// without it (worker_compile.cpp).
void removeOthers(const fs::path& cacheDir, const fs::path& kept) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(cacheDir, error))
        if (entry.path() != kept && entry.path().extension() != ".tmp") fs::remove_all(entry.path(), error);
}

}  // namespace

std::string precompiledHeaderDir(const PrecompiledHeaderRequest& request, std::string* why) {
    const std::string text = headerText(request.headersDir);
    ContentKey key;
    key.add(request.toolchain.dump());
    key.add(text);
    key.addFolder(request.headersDir);
    const fs::path cached = fs::path(request.cacheDir) / key.digest();
    if (fs::is_regular_file(cached / (std::string(kPrecompiledHeaderName) + ".gch"))) return cached.string();

    const fs::path work = request.workDir;
    CompileInputs host{(work / "src").string(), request.headersDir, (work / "objects").string(), (work / "out").string(), ""};
    for (const std::string& dir : {host.sources, host.objects, host.output}) fs::create_directories(dir);
    std::ofstream(fs::path(host.sources) / kPrecompiledHeaderName, std::ios::binary) << text;

    const CompileSandbox& sandbox = CompileSandbox::detect();
    const CompileInputs inside = sandbox.visiblePaths(host);
    std::vector<std::string> command = compilerCommand(request.toolchain);
    const std::string gch = std::string(kPrecompiledHeaderName) + ".gch";
    command.insert(command.end(), {"-I" + inside.headers, "-x", "c++-header", (fs::path(inside.sources) / kPrecompiledHeaderName).string(), "-o",
                                   (fs::path(inside.output) / gch).string()});
    const ProcessResult result = sandbox.run(host, command, request.limits);
    if (!result.succeeded() || !fs::is_regular_file(fs::path(host.output) / gch)) {
        *why = "the student headers did not precompile: " + (result.output.empty() ? result.failure : firstError(result.output));
        return "";
    }
    // Both files under a name of this process, then one rename: a concurrent grader that
    // published first wins, and either entry is right.
    std::error_code error;
    const fs::path temporary = cached.string() + "." + std::to_string(getpid()) + ".tmp";
    fs::create_directories(temporary, error);
    if (!error) fs::copy_file(fs::path(host.sources) / kPrecompiledHeaderName, temporary / kPrecompiledHeaderName, error);
    if (!error) fs::copy_file(fs::path(host.output) / gch, temporary / gch, error);
    if (!error) fs::rename(temporary, cached, error);
    if (error) fs::remove_all(temporary, error);
    if (fs::is_regular_file(cached / gch)) {
        removeOthers(request.cacheDir, cached);
        return cached.string();
    }
    // Not kept (a read-only build tree): this grading still has it.
    fs::copy_file(fs::path(host.sources) / kPrecompiledHeaderName, fs::path(host.output) / kPrecompiledHeaderName, error);
    if (error) *why = host.output + ": " + error.message();
    return error ? std::string() : host.output;
}

std::vector<std::string> precompiledHeaderFlags(const CompileInputs& seen) {
    if (seen.precompiled.empty()) return {};
    return {"-include", (fs::path(seen.precompiled) / kPrecompiledHeaderName).string()};
}

}  // namespace rtlab::grader
