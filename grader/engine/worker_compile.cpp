#include "grader/engine/worker_compile.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>
#include <vector>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::vector<std::string> compilerCommand(const nlohmann::json& toolchain) {
    std::vector<std::string> command = {fs::canonical(toolchain.at("compiler").get<std::string>()).string()};
    for (const auto& flag : toolchain.at("compile_flags")) command.push_back(flag.get<std::string>());
    return command;
}

// The limits of a process started at `now` under the deadline: the wall-clock time left.
ProcessLimits within(ProcessLimits limits, Clock::time_point deadline) {
    limits.wallSeconds = std::max(0.0, std::chrono::duration<double>(deadline - Clock::now()).count());
    return limits;
}

// Appends a process's output to the log, keeping at most one process's worth in all.
void appendOutput(WorkerCompile& compile, const ProcessResult& result, size_t capacity) {
    size_t room = capacity - std::min(capacity, compile.log.size());
    compile.log += result.output.substr(0, room);
    compile.droppedBytes += result.droppedBytes + (result.output.size() - std::min(room, result.output.size()));
    if (result.timedOut) compile.timedOut = true;
    if (!result.succeeded() && compile.failure.empty()) compile.failure = result.failure;
}

}  // namespace

WorkerCompile compileWorker(const CompileSandbox& sandbox, const CompileInputs& host, const nlohmann::json& toolchain,
                            const ProcessLimits& limits) {
    const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.wallSeconds));
    const CompileInputs inside = sandbox.visiblePaths(host);
    std::vector<fs::path> sources;
    for (const auto& entry : fs::recursive_directory_iterator(host.sources))
        if (entry.path().extension() == ".cpp") sources.push_back(entry.path().lexically_relative(host.sources));
    std::sort(sources.begin(), sources.end());
    fs::create_directories(fs::path(host.output) / "objects");
    // Objects are numbered, so no file name of the submission reaches the link line twice.
    auto objectOf = [&](size_t i) { return (fs::path(inside.output) / "objects" / (std::to_string(i) + ".o")).string(); };

    std::vector<ProcessResult> results(sources.size());
    std::atomic<size_t> next{0};
    auto compileSome = [&] {
        for (size_t i; (i = next++) < sources.size();) {
            std::vector<std::string> command = compilerCommand(toolchain);
            command.insert(command.end(), {"-I" + inside.headers, "-I" + inside.sources, "-c", (fs::path(inside.sources) / sources[i]).string(),
                                           "-o", objectOf(i)});
            results[i] = sandbox.run(host, command, within(limits, deadline));
        }
    };
    size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 4);
    std::vector<std::thread> pool;
    for (size_t t = 1; t < std::min(threads, sources.size()); ++t) pool.emplace_back(compileSome);
    compileSome();
    for (std::thread& t : pool) t.join();

    WorkerCompile compile;
    for (const ProcessResult& result : results) appendOutput(compile, result, limits.outputBytes);
    if (!std::all_of(results.begin(), results.end(), [](const ProcessResult& r) { return r.succeeded(); })) return compile;

    std::vector<std::string> link = {compilerCommand(toolchain).front()};
    for (size_t i = 0; i < sources.size(); ++i) link.push_back(objectOf(i));
    std::vector<fs::path> objects;
    for (const auto& entry : fs::directory_iterator(host.objects)) objects.push_back(entry.path().filename());
    std::sort(objects.begin(), objects.end());
    for (const fs::path& object : objects) link.push_back((fs::path(inside.objects) / object).string());
    for (const auto& flag : toolchain.at("link_flags")) link.push_back(flag.get<std::string>());
    link.insert(link.end(), {"-o", (fs::path(inside.output) / "rtlab-worker").string()});
    ProcessResult linked = sandbox.run(host, link, within(limits, deadline));
    appendOutput(compile, linked, limits.outputBytes);
    compile.succeeded = linked.succeeded() && fs::is_regular_file(fs::path(host.output) / "rtlab-worker");
    return compile;
}

}  // namespace rtlab::grader
