#include "grader/engine/stub_object_cache.h"

#include "grader/engine/cache_files.h"
#include "grader/engine/compiler_messages.h"
#include "grader/engine/precompiled_header.h"
#include "grader/engine/submission_toolchain.h"

#include <filesystem>
#include <fstream>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// Everything the object depends on: the toolchain, every stub and every header, with their
// paths.
std::string cacheKey(const StubObjectRequest& request) {
    ContentKey key;
    key.add(request.toolchain.dump());
    for (const auto& [path, contents] : request.stubs) {
        key.add(path);
        key.add(contents);
    }
    key.addFolder(request.headersDir);
    key.add(request.precompiledDir.empty() ? std::string() : kPrecompiledHeaderName);
    return key.digest();
}

}  // namespace

std::string compiledStubObject(const StubObjectRequest& request, std::string* why) {
    const fs::path cached = fs::path(request.cacheDir) / (cacheKey(request) + ".o");
    if (fs::is_regular_file(cached)) return cached.string();

    std::error_code error;
    fs::create_directories(request.cacheDir, error);
    if (error) {
        *why = request.cacheDir + ": " + error.message();
        return "";
    }
    const fs::path work = request.workDir;
    CompileInputs host{(work / "src").string(), request.headersDir, (work / "objects").string(), (work / "out").string(), request.precompiledDir};
    for (const std::string& dir : {host.sources, host.objects, host.output}) fs::create_directories(dir);
    for (const auto& [path, contents] : request.stubs) {
        fs::create_directories((fs::path(host.sources) / path).parent_path());
        std::ofstream(fs::path(host.sources) / path, std::ios::binary) << contents;
    }

    // One relocatable object (-r) of all the stubs: no start files, no libraries, nothing
    // resolved yet; the submission's link resolves it with the rest.
    const CompileSandbox& sandbox = CompileSandbox::detect();
    CompileInputs inside = sandbox.visiblePaths(host);
    std::vector<std::string> command = compilerCommand(request.toolchain);
    const std::vector<std::string> precompiled = precompiledHeaderFlags(inside);
    command.insert(command.end(), precompiled.begin(), precompiled.end());
    command.insert(command.end(), {"-I" + inside.headers, "-I" + inside.sources, "-r", "-nostdlib"});
    for (const auto& [path, contents] : request.stubs)
        if (fs::path(path).extension() == ".cpp") command.push_back((fs::path(inside.sources) / path).string());
    command.insert(command.end(), {"-o", (fs::path(inside.output) / "stubs.o").string()});
    ProcessResult result = sandbox.run(host, command, request.limits);
    const fs::path built = fs::path(host.output) / "stubs.o";
    if (!result.succeeded() || !fs::is_regular_file(built)) {
        *why = "the committed stubs did not compile: " + (result.output.empty() ? result.failure : firstError(result.output));
        return "";
    }
    if (!publishCopy(built, cached)) return built.string();  // this run can still use it
    return cached.string();
}

}  // namespace rtlab::grader
