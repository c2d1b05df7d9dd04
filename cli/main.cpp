// rtlab and rtlab-solution share this entry point; they differ only in which implementation
// of the assignments they link (docs/layout.md). Grading is not done here: `grade` hands over
// to rtlab-grader, which links no assignment code, with this executable's worker
// (RTLAB_WORKER: rtlab-worker or rtlab-worker-solution, built beside it).
#include "cli/run.h"

#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

int handOverToGrader(int argc, char** argv) {
    std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe").parent_path();
    std::string grader = (dir / "rtlab-grader").string(), worker = (dir / RTLAB_WORKER).string();
    std::vector<std::string> arguments = {grader, "grade", "--worker", worker};
    for (int i = 2; i < argc; ++i) arguments.emplace_back(argv[i]);
    std::vector<char*> pointers;
    for (std::string& a : arguments) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    execv(grader.c_str(), pointers.data());
    std::cerr << "rtlab: cannot run " << grader << ": " << std::strerror(errno) << " (build it with make build)\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "grade") == 0) return handOverToGrader(argc, argv);
    return rtlab::cli::run(argc, argv);
}
