#include "grader/engine/submission_build.h"

#include "framework/core/error.h"
#include "grader/engine/compile_sandbox.h"
#include "grader/engine/parallel_jobs.h"
#include "grader/engine/precompiled_header.h"
#include "grader/engine/stub_object_cache.h"
#include "grader/engine/submission_files.h"
#include "grader/engine/submission_toolchain.h"
#include "grader/engine/worker_compile.h"
#include "grader/engine/worker_sources.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

constexpr uintmax_t kMaxFileBytes = uintmax_t(1) << 20;
constexpr size_t kMaxFiles = 200;
// The framework headers a student file may include: the assignment interfaces and what they
// build on. The renderer, the oracle and the reference renderers are not among them.
constexpr const char* kStudentHeaderFolders[] = {"framework/core", "framework/interface", "framework/accel", "framework/scene"};

void writeFile(const fs::path& path, const std::string& contents) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << contents;
    if (!out) throw Error(path.string() + ": cannot be written");
}

// A framework file (a student header) read for the compile sandbox.
std::string readFrameworkFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string contents(std::istreambuf_iterator<char>(in), {});
    if (!in.good() && !in.eof()) throw Error(path.string() + ": cannot be read");
    return contents;
}

bool isSource(const fs::path& p) { return p.extension() == ".cpp" || p.extension() == ".h" || p.extension() == ".hpp"; }

// Where a submission keeps the file that replaces stub `relative` (assignments/a0_intersect/
// ray_box.cpp): under the same path, without the assignments/ prefix, or flat by file name.
std::optional<fs::path> findInSubmission(const SubmissionFolder& submission, const fs::path& relative) {
    fs::path withoutRoot = relative.lexically_relative("assignments");
    for (const fs::path& candidate : {relative, withoutRoot, relative.filename()})
        if (submission.kind(candidate) != SubmissionFolder::Kind::Missing) return candidate;
    return std::nullopt;
}

// The stubs, replaced file by file by the submission's, plus the submission's own helper
// sources and headers in its assignment folders. Returns the files taken from the submission.
std::vector<std::string> mergeSources(const SubmissionFolder& submission, const std::map<std::string, std::string>& stubs, const fs::path& into) {
    std::vector<std::string> taken;
    std::set<fs::path> assignments;
    for (const auto& [name, contents] : stubs) {
        fs::path relative = name;
        assignments.insert(relative.parent_path());
        auto replacement = findInSubmission(submission, relative);
        writeFile(into / relative, replacement ? submission.read(*replacement, kMaxFileBytes) : contents);
        if (replacement) taken.push_back((submission.root() / *replacement).string());
    }
    for (const fs::path& assignment : assignments) {
        fs::path name = assignment.filename();
        for (const fs::path& folder : {fs::path("assignments") / name, name}) {
            if (submission.kind(folder) != SubmissionFolder::Kind::Folder) continue;
            for (const std::string& entry : submission.list(folder)) {
                if (!isSource(entry) || stubs.count((assignment / entry).string())) continue;
                if (taken.size() >= kMaxFiles) throw Error(submission.root().string() + ": more than 200 source files");
                writeFile(into / assignment / entry, submission.read(folder / entry, kMaxFileBytes));
                taken.push_back((submission.root() / folder / entry).string());
            }
        }
    }
    return taken;
}

void copyStudentHeaders(const fs::path& sourceDir, const fs::path& into) {
    for (const char* folder : kStudentHeaderFolders)
        for (const auto& entry : fs::directory_iterator(sourceDir / folder))
            if (entry.path().extension() == ".h") writeFile(into / folder / entry.path().filename(), readFrameworkFile(entry.path()));
}

// The committed stubs of folders not in `graded` (all of them are graded when it is empty),
// moved out of stubs, by folder.
std::map<std::string, std::map<std::string, std::string>> takeUngraded(std::map<std::string, std::string>& stubs,
                                                                       const std::vector<std::string>& graded) {
    std::map<std::string, std::map<std::string, std::string>> ungraded;
    if (graded.empty()) return ungraded;
    for (auto it = stubs.begin(); it != stubs.end();) {
        std::string folder = fs::path(it->first).lexically_relative("assignments").begin()->string();
        if (std::find(graded.begin(), graded.end(), folder) == graded.end()) {
            ungraded[folder].insert(*it);
            it = stubs.erase(it);
        } else {
            ++it;
        }
    }
    return ungraded;
}

}  // namespace

SubmissionBuild buildSubmission(const std::string& submissionDir, const std::string& sourceDir, std::map<std::string, std::string> stubs,
                                const std::string& toolchainPath, const std::string& workDir, const CompileLimits& limits,
                                const std::vector<std::string>& gradedFolders) {
    SubmissionFolder submission(submissionDir);
    nlohmann::json toolchain = readToolchain(toolchainPath);
    const CompileSandbox& sandbox = CompileSandbox::detect();
    ProcessLimits processLimits;
    processLimits.wallSeconds = limits.wallSeconds;
    processLimits.cpuSeconds = static_cast<int>(limits.wallSeconds) + 1;
    processLimits.memoryMiB = limits.memoryMiB;

    SubmissionBuild build;
    // The runtime is copied, so the compiler needs nothing of the build tree (whose folders an
    // unprivileged user may not be able to enter).
    CompileInputs host{(fs::path(workDir) / "src").string(), (fs::path(workDir) / "include").string(),
                       (fs::path(workDir) / "objects").string(), (fs::path(workDir) / "out").string(), ""};
    fs::create_directories(host.output);
    fs::create_directories(host.objects);
    fs::copy_file(toolchain.at("worker_runtime").get<std::string>(), fs::path(host.objects) / "worker-runtime.o",
                  fs::copy_options::overwrite_existing);
    copyStudentHeaders(sourceDir, host.headers);
    // The committed code compiled once per cache key (the stubs, the student headers), not the
    // submission: the submission's compile limit is for its own files, and a loaded machine may
    // need more than that for the rest. Still a hard limit.
    ProcessLimits committedCodeLimits = processLimits;
    committedCodeLimits.wallSeconds = std::max(limits.wallSeconds, kStubCompileSeconds);
    committedCodeLimits.cpuSeconds = static_cast<int>(committedCodeLimits.wallSeconds) + 1;
    // The student headers precompiled, kept like the stubs' object, for the stubs and the
    // submission. Only in the namespace sandbox: without it the compiler runs as nobody, who may
    // not reach the build tree where they are kept. Without them every file still compiles,
    // only slower.
    if (sandbox.usesNamespaces()) {
        std::string why;
        host.precompiled = precompiledHeaderDir({host.headers, toolchain, (fs::path(toolchainPath).parent_path() / "precompiled-headers").string(),
                                                 (fs::path(workDir) / "precompiled").string(), committedCodeLimits},
                                                &why);
        if (host.precompiled.empty()) build.slower.push_back("slower: every file compiled without the precompiled student headers, as they could not be made: " + why);
    }
    // The assignments not graded link their committed stubs: an object per assignment folder,
    // compiled once for every grading run that leaves the folder out, whichever others it
    // grades, and the folders new to the cache side by side. A folder whose object cannot be
    // had compiles with the submission as before.
    std::vector<std::pair<std::string, std::map<std::string, std::string>>> ungraded;
    for (auto& folder : takeUngraded(stubs, gradedFolders)) ungraded.emplace_back(std::move(folder));
    std::vector<std::string> objects(ungraded.size()), reasons(ungraded.size());
    runInParallel(ungraded.size(), compileThreads(), [&](size_t i) {
        const auto& [folder, folderStubs] = ungraded[i];
        try {
            objects[i] = compiledStubObject({folderStubs, host.headers, toolchain, (fs::path(toolchainPath).parent_path() / "stub-objects").string(),
                                             (fs::path(workDir) / "stubs" / folder).string(), committedCodeLimits, host.precompiled},
                                            &reasons[i]);
        } catch (const std::exception& e) {
            reasons[i] = e.what();
        }
    });
    std::string uncompiled, why;
    for (size_t i = 0; i < ungraded.size(); ++i) {
        auto& [folder, folderStubs] = ungraded[i];
        if (objects[i].empty()) {
            uncompiled += (uncompiled.empty() ? "" : ", ") + folder;
            if (why.empty()) why = reasons[i];
            stubs.merge(folderStubs);
        } else {
            fs::copy_file(objects[i], fs::path(host.objects) / ("stubs-" + folder + ".o"), fs::copy_options::overwrite_existing);
        }
    }
    if (!uncompiled.empty())
        build.slower.push_back("slower: the committed stubs of " + uncompiled + " compiled with the submission, as they could not be compiled once: " + why);
    build.fromSubmission = mergeSources(submission, stubs, host.sources);

    WorkerCompile compile =
        compileWorker(sandbox, host, toolchain, processLimits, (fs::path(toolchainPath).parent_path() / "unit-objects").string());
    build.log = compile.log;
    if (compile.droppedBytes > 0) build.log += "\n[" + std::to_string(compile.droppedBytes) + " more bytes of compiler output not shown]\n";
    if (compile.timedOut) build.log = "the compiler was stopped after the limit of " + std::to_string(int(limits.wallSeconds)) + " s\n" + build.log;
    else if (!compile.succeeded && build.log.empty()) build.log = "the compiler failed: " + compile.failure + "\n";
    build.executable = (fs::path(host.output) / "rtlab-worker").string();
    build.succeeded = compile.succeeded;
    build.sources = compile.sources;
    build.cached = compile.cached;
    // Written by the grader after the compile, over anything the compile left there.
    if (build.succeeded) writeWorkerSources((fs::path(host.sources) / "assignments").string(), build.executable);
    return build;
}

}  // namespace rtlab::grader
