#include "grader/submission_build.h"

#include "framework/core/error.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <sys/wait.h>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

void appendArgument(std::string& command, const std::string& argument) {
    command += ' ';
    command += quote(argument);
}

// Runs a shell command; returns its exit status and appends its output to log.
int run(const std::string& command, std::string& log) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) throw Error("grader: cannot run " + command);
    std::array<char, 4096> buffer;
    size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) log.append(buffer.data(), n);
    int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// Where a submission keeps the file that replaces stub `relative` (assignments/a0_intersect/
// ray_box.cpp): under the same path, without the assignments/ prefix, or flat by file name.
std::optional<fs::path> findInSubmission(const fs::path& submission, const fs::path& relative) {
    fs::path withoutRoot = relative.lexically_relative("assignments");
    for (const fs::path& candidate : {submission / relative, submission / withoutRoot, submission / relative.filename()})
        if (fs::is_regular_file(candidate)) return candidate;
    return std::nullopt;
}

// Student code may only run when the grader calls it, inside the sandbox. Constructors and
// destructors of global objects (and __attribute__((constructor))) would run before main or
// at exit, outside it: their sections are removed, with a note in the build log. An ifunc
// resolver runs while the program is loaded and cannot be removed: the build is refused.
// Returns the refusal, or "" when the object may be linked.
std::string removeCodeOutsideCalls(const std::string& object, const std::string& name, std::string& log) {
    std::string listing;
    run("readelf -W -S -s " + quote(object), listing);
    if (listing.find(" IFUNC ") != std::string::npos) return name + ": refused, it defines an ifunc resolver\n";
    std::string strip;
    for (const char* section : {".init_array", ".preinit_array", ".ctors", ".fini_array", ".dtors"})
        if (listing.find(std::string(" ") + section + " ") != std::string::npos)
            strip += std::string(" --remove-section=") + section + " --remove-section=.rela" + section;
    if (strip.empty()) return "";
    std::string output;
    if (run("objcopy" + strip + " " + quote(object), output) != 0) return name + ": could not be prepared: " + output;
    log += name + ": note: constructors and destructors of global objects in this file are not run (the grader runs "
                  "your code only when it calls your functions); use function-local statics instead\n";
    return "";
}

}  // namespace

SubmissionBuild buildSubmission(const std::string& submissionDir, const std::string& sourceDir, const std::string& toolchainPath,
                                const std::string& workDir) {
    if (!fs::is_directory(submissionDir)) throw Error(submissionDir + ": the submission folder does not exist");
    std::ifstream in(toolchainPath);
    if (!in) throw Error(toolchainPath + ": missing; build rtlab first (make build)");
    nlohmann::json toolchain;
    try {
        toolchain = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(toolchainPath + ": malformed (" + e.what() + ")");
    }

    SubmissionBuild build;
    fs::create_directories(workDir);
    std::string compile = quote(toolchain.at("compiler").get<std::string>());
    appendArgument(compile, "-I" + (fs::path(workDir) / "src").string());
    for (const auto& flag : toolchain.at("compile_flags")) appendArgument(compile, flag.get<std::string>());
    for (const auto& dir : toolchain.at("include_dirs")) appendArgument(compile, "-I" + dir.get<std::string>());

    // The stub set defines which files exist; the submission replaces them one by one, and
    // extra .cpp files in its assignment folders are compiled too (helpers).
    std::vector<std::pair<fs::path, fs::path>> sources;  // (source, object)
    fs::path stubs = fs::path(sourceDir) / "assignments";
    for (const auto& entry : fs::recursive_directory_iterator(stubs)) {
        if (entry.path().extension() != ".cpp") continue;
        fs::path relative = entry.path().lexically_relative(sourceDir);
        auto replacement = findInSubmission(submissionDir, relative);
        if (replacement) build.fromSubmission.push_back(replacement->string());
        sources.push_back({replacement ? *replacement : entry.path(), relative});
    }
    for (const auto& assignment : fs::directory_iterator(stubs)) {
        fs::path name = assignment.path().filename();
        for (const fs::path& folder : {fs::path(submissionDir) / "assignments" / name, fs::path(submissionDir) / name}) {
            if (!fs::is_directory(folder)) continue;
            for (const auto& entry : fs::directory_iterator(folder))
                if (entry.path().extension() == ".cpp" && !fs::exists(stubs / name / entry.path().filename())) {
                    build.fromSubmission.push_back(entry.path().string());
                    sources.push_back({entry.path(), fs::path("assignments") / name / entry.path().filename()});
                }
        }
    }

    // Headers of the submission sit next to its copied sources, and src/ comes first on the
    // include path, so both "helper.h" and "assignments/a1_bvh/helper.h" find them.
    for (const auto& assignment : fs::directory_iterator(stubs)) {
        fs::path name = assignment.path().filename();
        fs::path target = fs::path(workDir) / "src" / "assignments" / name;
        fs::create_directories(target);
        for (const fs::path& folder : {fs::path(submissionDir) / "assignments" / name, fs::path(submissionDir) / name, fs::path(submissionDir)}) {
            if (!fs::is_directory(folder)) continue;
            for (const auto& entry : fs::directory_iterator(folder))
                if (entry.path().extension() == ".h" || entry.path().extension() == ".hpp")
                    fs::copy_file(entry.path(), target / entry.path().filename(), fs::copy_options::overwrite_existing);
        }
    }

    // A stub the submission does not replace is already compiled in the build tree.
    auto prebuilt = [&](const fs::path& relative) -> std::optional<std::string> {
        std::string suffix = (fs::path("/") / relative).string();
        suffix += ".o";
        for (const auto& object : toolchain.value("stub_objects", nlohmann::json::array())) {
            std::string path = object.get<std::string>();
            if (path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0) return path;
        }
        return std::nullopt;
    };
    std::vector<std::string> objects;
    for (const auto& [source, relative] : sources) {
        if (source.lexically_relative(sourceDir) == relative) {
            if (auto object = prebuilt(relative)) {
                objects.push_back(*object);
                continue;
            }
        }
        fs::path object = fs::path(workDir) / "objects" / relative;
        object.replace_extension(".o");
        fs::create_directories(object.parent_path());
        // Copied next to the object so a diagnostic names the student's file by its place in
        // the assignment tree.
        fs::path copy = fs::path(workDir) / "src" / relative;
        fs::create_directories(copy.parent_path());
        fs::copy_file(source, copy, fs::copy_options::overwrite_existing);
        std::string log;
        if (run(compile + " -c " + quote(copy.string()) + " -o " + quote(object.string()), log) != 0) {
            build.log += log;
            continue;
        }
        build.log += log;
        if (std::string refusal = removeCodeOutsideCalls(object.string(), relative.string(), build.log); !refusal.empty()) {
            build.log += refusal;
            continue;
        }
        objects.push_back(object.string());
    }
    if (objects.size() != sources.size()) return build;

    std::string link = compile;
    appendArgument(link, toolchain.at("main_object").get<std::string>());
    appendArgument(link, "-Wl,--whole-archive");
    for (const auto& archive : toolchain.at("archives")) appendArgument(link, archive.get<std::string>());
    appendArgument(link, "-Wl,--no-whole-archive");
    for (const std::string& object : objects) appendArgument(link, object);
    for (const auto& library : toolchain.at("libraries")) appendArgument(link, library.get<std::string>());
    build.executable = (fs::path(workDir) / "rtlab-submission").string();
    appendArgument(link, "-o");
    appendArgument(link, build.executable);
    std::string log;
    build.succeeded = run(link, log) == 0;
    build.log += log;
    return build;
}

}  // namespace rtlab::grader
