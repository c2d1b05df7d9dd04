#include "grader/engine/compile_sandbox.h"

#include <filesystem>
#include <sys/stat.h>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBubblewrap = "/usr/bin/bwrap";
const std::vector<std::string> kEnvironment = {"PATH=/usr/bin", "LC_ALL=C"};

// The toolchain and system headers: what a compiler needs of /usr, and not /usr/share,
// /usr/local or /usr/src.
std::vector<std::string> systemMounts() {
    std::vector<std::string> args;
    for (const char* dir : {"/usr/bin", "/usr/lib", "/usr/libexec", "/usr/include", "/usr/lib64"})
        args.insert(args.end(), {"--ro-bind-try", dir, dir});
    args.insert(args.end(), {"--symlink", "usr/bin", "/bin", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64", "/lib64"});
    return args;
}

std::vector<std::string> isolation() {
    return {"--unshare-all", "--die-with-parent", "--new-session", "--cap-drop", "ALL", "--unshare-user", "--uid", "65534", "--gid", "65534",
            "--dev", "/dev", "--tmpfs", "/tmp", "--clearenv", "--setenv", "PATH", "/usr/bin", "--setenv", "LC_ALL", "C"};
}

const CompileInputs kInside = {"/src", "/include", "/objects", "/out", "/precompiled"};

}  // namespace

const CompileSandbox& CompileSandbox::detect() {
    static const CompileSandbox sandbox = [] {
        CompileSandbox s;
        if (!fs::exists(kBubblewrap)) {
            s.whyNot_ = "bubblewrap is not installed";
            return s;
        }
        std::vector<std::string> probe = {kBubblewrap};
        for (auto part : {isolation(), systemMounts()}) probe.insert(probe.end(), part.begin(), part.end());
        probe.insert(probe.end(), {"--", "/usr/bin/true"});
        ProcessLimits limits;
        limits.wallSeconds = 10;
        ProcessResult r = runProcess(probe, kEnvironment, limits);
        s.bubblewrap_ = r.succeeded();
        if (!s.bubblewrap_) s.whyNot_ = "bubblewrap cannot create namespaces here (" + r.failure + ")";
        return s;
    }();
    return sandbox;
}

std::string CompileSandbox::description() const {
    if (bubblewrap_)
        return "the compiler ran in a bubblewrap mount namespace holding only the submission, the student headers, the system "
               "toolchain and headers and the worker runtime (no network, no other processes, user nobody), with time, CPU and "
               "memory limits and stdin closed";
    return "the compiler ran as the unprivileged user nobody on the real file system (" + whyNot_ +
           "): it could read any world-readable file; time, CPU and memory limits and stdin closed";
}

CompileInputs CompileSandbox::visiblePaths(const CompileInputs& host) const {
    if (!bubblewrap_) return host;
    CompileInputs inside = kInside;
    if (host.precompiled.empty()) inside.precompiled.clear();
    return inside;
}

ProcessResult CompileSandbox::run(const CompileInputs& host, const std::vector<std::string>& command, ProcessLimits limits) const {
    if (!bubblewrap_) {
        // nobody must reach the inputs and write the output; nothing else is shared with it.
        for (const std::string& dir : {host.sources, host.headers, host.objects, host.output}) chmod(dir.c_str(), 0755);
        chmod(host.output.c_str(), 0777);
        limits.asNobody = true;
        return runProcess(command, kEnvironment, limits);
    }
    std::vector<std::string> argv = {kBubblewrap};
    for (auto part : {isolation(), systemMounts()}) argv.insert(argv.end(), part.begin(), part.end());
    argv.insert(argv.end(), {"--ro-bind", host.sources, kInside.sources, "--ro-bind", host.headers, kInside.headers, "--ro-bind",
                             host.objects, kInside.objects, "--bind", host.output, kInside.output, "--chdir", kInside.sources});
    if (!host.precompiled.empty()) argv.insert(argv.end(), {"--ro-bind", host.precompiled, kInside.precompiled});
    argv.push_back("--");
    argv.insert(argv.end(), command.begin(), command.end());
    return runProcess(argv, kEnvironment, limits);
}

}  // namespace rtlab::grader
