#include "grader/engine/stub_object_cache.h"

#include "framework/core/sha256.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Everything the object depends on: the toolchain, every stub and every header, with their
// paths, each length-prefixed so that no two different inputs run together into one text.
std::string cacheKey(const StubObjectRequest& request) {
    std::string text;
    auto add = [&](const std::string& part) { text += std::to_string(part.size()) + ":" + part; };
    add(request.toolchain.dump());
    for (const auto& [path, contents] : request.stubs) {
        add(path);
        add(contents);
    }
    std::set<fs::path> headers;
    for (const auto& entry : fs::recursive_directory_iterator(request.headersDir))
        if (entry.is_regular_file()) headers.insert(entry.path());
    for (const fs::path& header : headers) {
        add(header.lexically_relative(request.headersDir).string());
        add(readAll(header));
    }
    return sha256Hex(text);
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
    CompileInputs host{(work / "src").string(), request.headersDir, (work / "objects").string(), (work / "out").string()};
    for (const std::string& dir : {host.sources, host.objects, host.output}) fs::create_directories(dir);
    for (const auto& [path, contents] : request.stubs) {
        fs::create_directories((fs::path(host.sources) / path).parent_path());
        std::ofstream(fs::path(host.sources) / path, std::ios::binary) << contents;
    }

    // One relocatable object (-r) of all the stubs: no start files, no libraries, nothing
    // resolved yet; the submission's link resolves it with the rest.
    const CompileSandbox& sandbox = CompileSandbox::detect();
    CompileInputs inside = sandbox.visiblePaths(host);
    std::vector<std::string> command = {fs::canonical(request.toolchain.at("compiler").get<std::string>()).string()};
    for (const auto& flag : request.toolchain.at("compile_flags")) command.push_back(flag.get<std::string>());
    command.insert(command.end(), {"-I" + inside.headers, "-I" + inside.sources, "-r", "-nostdlib"});
    for (const auto& [path, contents] : request.stubs)
        if (fs::path(path).extension() == ".cpp") command.push_back((fs::path(inside.sources) / path).string());
    command.insert(command.end(), {"-o", (fs::path(inside.output) / "stubs.o").string()});
    ProcessResult result = sandbox.run(host, command, request.limits);
    const fs::path built = fs::path(host.output) / "stubs.o";
    if (!result.succeeded() || !fs::is_regular_file(built)) {
        *why = "the committed stubs did not compile: " + (result.output.empty() ? result.failure : result.output);
        return "";
    }
    // Another grader may be filling the same entry: a rename is atomic, and either copy is right.
    const fs::path temporary = cached.string() + "." + std::to_string(getpid()) + ".tmp";
    fs::copy_file(built, temporary, fs::copy_options::overwrite_existing, error);
    if (!error) fs::rename(temporary, cached, error);
    if (error) {
        fs::remove(temporary, error);
        return built.string();  // this run can still use it
    }
    return cached.string();
}

}  // namespace rtlab::grader
