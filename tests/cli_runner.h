// Running the rtlab command line inside a test (cli::run, in process): its exit status and
// what it wrote to stdout and stderr.
#pragma once

#include "cli/run.h"

#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rtlab::test {

struct CliResult {
    int status = 0;
    std::string out;
    std::string err;
};

// The exit status alone; what the command writes goes to the test's own output.
inline int runCliStatus(std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), "rtlab");
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    return cli::run(static_cast<int>(argv.size()), argv.data());
}

inline CliResult runCli(std::vector<std::string> arguments) {
    std::ostringstream out, err;
    std::streambuf* originalOut = std::cout.rdbuf(out.rdbuf());
    std::streambuf* originalErr = std::cerr.rdbuf(err.rdbuf());
    int status = runCliStatus(std::move(arguments));
    std::cout.rdbuf(originalOut);
    std::cerr.rdbuf(originalErr);
    return {status, out.str(), err.str()};
}

}  // namespace rtlab::test
