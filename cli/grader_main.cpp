// rtlab-grader: the only process that reads expected answers, computes scores and writes
// reports (docs/grading.md, "Isolation and trust"). It links no assignment code: the code to
// grade runs in a worker executable (--worker), sandboxed. `rtlab grade` and
// `rtlab-solution grade` hand over to it with their own worker.
#include "cli/commands.h"
#include "framework/core/error.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"rtlab-grader: grades the code in a worker executable, or a student's submission"};
    app.require_subcommand(1);
    rtlab::cli::addGradeCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    } catch (const std::exception& e) {
        std::cerr << "rtlab-grader: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
