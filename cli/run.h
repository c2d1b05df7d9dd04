// rtlab's command line as a function, for main.cpp and for the tests that run a command in
// their own process (tests/cli_runner.h).
#pragma once

namespace rtlab::cli {

// Runs rtlab with the given arguments; returns the process exit code.
int run(int argc, char** argv);

}  // namespace rtlab::cli
