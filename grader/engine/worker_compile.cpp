#include "grader/engine/worker_compile.h"

#include "grader/engine/cache_files.h"
#include "grader/engine/parallel_jobs.h"
#include "grader/engine/precompiled_header.h"
#include "grader/engine/submission_toolchain.h"
#include "grader/engine/unit_object_cache.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

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

// One .cpp's own view of the sources: every header of the submission and that file, no
// other .cpp, with an output folder of its own; what its compile can read is then exactly
// what its cache key holds.
CompileInputs unitView(const CompileInputs& host, const std::vector<fs::path>& headers, const fs::path& source, const fs::path& at) {
    CompileInputs view{(at / "src").string(), host.headers, (at / "objects").string(), (at / "out").string(), host.precompiled};
    fs::remove_all(at);
    for (const fs::path& file : headers) {
        fs::create_directories((view.sources / file).parent_path());
        fs::copy_file(fs::path(host.sources) / file, view.sources / file);
    }
    fs::create_directories((view.sources / source).parent_path());
    fs::copy_file(fs::path(host.sources) / source, view.sources / source);
    fs::create_directories(view.objects);
    fs::create_directories(view.output);
    return view;
}

// Compiles one .cpp in its view (at viewDir) into objectTo. Never throws: it runs on the
// compile threads, and a file that cannot be written fails this unit's compile only.
ProcessResult compileUnit(const CompileSandbox& sandbox, const CompileInputs& host, const std::vector<fs::path>& headers,
                          const fs::path& source, const fs::path& viewDir, std::vector<std::string> command, const ProcessLimits& limits,
                          const fs::path& objectTo) {
    ProcessResult result;
    try {
        const CompileInputs view = unitView(host, headers, source, viewDir);
        const CompileInputs seen = sandbox.visiblePaths(view);
        command.insert(command.end(), {"-I" + seen.headers, "-I" + seen.sources, "-c", (fs::path(seen.sources) / source).string(), "-o",
                                       (fs::path(seen.output) / "unit.o").string()});
        ProcessLimits left = limits;
        if (!seen.precompiled.empty()) {
            std::vector<std::string> after = command;
            const std::vector<std::string> flags = precompiledHeaderFlags(seen);
            after.insert(after.begin() + 1, flags.begin(), flags.end());
            const Clock::time_point start = Clock::now();
            result = sandbox.run(view, after, limits);
            left.wallSeconds = std::max(0.0, limits.wallSeconds - std::chrono::duration<double>(Clock::now() - start).count());
        }
        // Without the precompiled header: none, or a file that compiles only without it (a name
        // of its own that clashes with one of the interfaces'); its messages are then this
        // compile's, as if there were no precompiled header. Both share the unit's time limit.
        if (seen.precompiled.empty() || (!result.succeeded() && !result.timedOut)) {
            CompileInputs alone = view;
            alone.precompiled.clear();  // not mounted either: it may have been removed since
            result = sandbox.run(alone, command, left);
        }
        if (result.succeeded()) fs::copy_file(fs::path(view.output) / "unit.o", objectTo, fs::copy_options::overwrite_existing);
    } catch (const fs::filesystem_error& e) {
        result.exitCode = -1;
        result.failure = source.string() + ": its compile could not be set up (" + e.code().message() + ")";
    }
    return result;
}

// The digest of what every unit's compile shares, for the cache key: the flags, the student
// headers and the submission's own headers, each with its path.
std::string sharedDigest(const CompileInputs& host, const nlohmann::json& toolchain, const std::vector<fs::path>& headers) {
    ContentKey key;
    key.add(toolchain.at("compile_flags").dump());
    key.addFolder(host.headers);
    key.add(host.precompiled.empty() ? std::string() : kPrecompiledHeaderName);
    for (const fs::path& file : headers) key.addFile(file.string(), fs::path(host.sources) / file);
    return key.digest();
}

}  // namespace

WorkerCompile compileWorker(const CompileSandbox& sandbox, const CompileInputs& host, const nlohmann::json& toolchain,
                            const ProcessLimits& limits, const std::string& cacheDir) {
    const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.wallSeconds));
    const CompileInputs inside = sandbox.visiblePaths(host);
    std::vector<fs::path> sources, headers;
    for (const auto& entry : fs::recursive_directory_iterator(host.sources)) {
        if (!entry.is_regular_file()) continue;
        (entry.path().extension() == ".cpp" ? sources : headers).push_back(entry.path().lexically_relative(host.sources));
    }
    std::sort(sources.begin(), sources.end());
    std::sort(headers.begin(), headers.end());
    fs::create_directories(fs::path(host.output) / "objects");
    // Objects are numbered, so no file name of the submission reaches the link line twice.
    auto objectOf = [&](const std::string& output, size_t i) { return (fs::path(output) / "objects" / (std::to_string(i) + ".o")).string(); };
    const std::vector<std::string> compiler = compilerCommand(toolchain);
    // Only where the namespace shows each compile its view alone: without it the compiler could
    // read any file, and its object could depend on more than the key.
    UnitObjectCache cache(sandbox.usesNamespaces() ? fs::path(cacheDir) : fs::path(), compiler.front(), sharedDigest(host, toolchain, headers));
    const fs::path views = fs::path(host.sources).parent_path() / "units";

    std::vector<ProcessResult> results(sources.size());
    std::vector<std::string> keys(sources.size());
    std::vector<size_t> toCompile;
    for (size_t i = 0; i < sources.size(); ++i) {
        keys[i] = cache.key(sources[i].string(), readBytes(fs::path(host.sources) / sources[i]));
        if (cache.fetch(keys[i], objectOf(host.output, i), &results[i].output)) results[i].exitCode = 0;
        else toCompile.push_back(i);
    }
    runInParallel(toCompile.size(), compileThreads(), [&](size_t n) {
        const size_t i = toCompile[n];
        const fs::path object = objectOf(host.output, i);
        results[i] = compileUnit(sandbox, host, headers, sources[i], views / std::to_string(i), compiler, within(limits, deadline), object);
        // Messages cut short are not kept: a later grading would show less than this one.
        if (results[i].succeeded() && results[i].droppedBytes == 0) cache.store(keys[i], object, results[i].output);
    });

    WorkerCompile compile;
    compile.sources = sources.size();
    compile.cached = sources.size() - toCompile.size();
    for (const ProcessResult& result : results) appendOutput(compile, result, limits.outputBytes);
    if (!std::all_of(results.begin(), results.end(), [](const ProcessResult& r) { return r.succeeded(); })) return compile;

    std::vector<std::string> link = {compiler.front()};
    for (size_t i = 0; i < sources.size(); ++i) link.push_back(objectOf(inside.output, i));
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
