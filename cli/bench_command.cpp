// rtlab bench [OPTIONS]: runs the benchmark executable that belongs to this one — rtlab-bench
// next to rtlab, rtlab-solution-bench next to rtlab-solution — with the same arguments
// (docs/performance.md). The benchmarks live in their own executables so that only they link
// Embree, the peer they are measured against; they are built where libembree-dev is installed.
#include "cli/commands.h"
#include "framework/core/error.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace rtlab::cli {
namespace {

[[noreturn]] void execBenchmark(const std::vector<std::string>& arguments) {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (error) throw Error("rtlab bench: cannot find this executable (/proc/self/exe): " + error.message());
    fs::path benchmark = self.parent_path() / (self.filename().string() + "-bench");
    if (!fs::exists(benchmark))
        throw Error(benchmark.string() +
                    " is not built: the benchmarks need Embree (Debian libembree-dev, scripts/install-deps), "
                    "then rebuild");
    // argv[0] is what the benchmark's --help and usage lines call it: the command the student
    // typed ("rtlab bench", "rtlab-solution bench"), not the executable it is run from.
    std::vector<std::string> args{self.filename().string() + " bench"};
    args.insert(args.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(benchmark.c_str(), argv.data());
    throw Error(benchmark.string() + ": cannot run it: " + std::strerror(errno));
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    CLI::App* bench = app.add_subcommand(
        "bench", "Accelerators against Embree, and run time against error (rtlab bench --help; docs/performance.md)");
    bench->prefix_command();  // every argument after "bench" goes to the benchmark executable,
    bench->set_help_flag();   // --help included
    bench->callback([bench] { execBenchmark(bench->remaining()); });
}

}  // namespace rtlab::cli
