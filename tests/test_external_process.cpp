// Running an external renderer (framework/external/external_process.h): its exit status, the
// hard time limit, and the one-line error with the install hint when it is missing. Uses
// /bin/sh, present on every machine the project builds on.
#include "framework/core/error.h"
#include "framework/external/external_process.h"
#include "framework/external/temporary_directory.h"

#include <doctest/doctest.h>

#include <fstream>
#include <iterator>
#include <string>

using namespace rtlab;

TEST_CASE("external process: exit status and output in the log") {
    TemporaryDirectory work("rtlab-test-external");
    auto log = work.path() / "log.txt";
    ExternalRun run = runExternal("sh", {"-c", "echo out; echo err >&2; exit 3"}, work.path(), log, 30.0, "hint");
    CHECK_FALSE(run.timedOut);
    CHECK(run.exitStatus == 3);
    CHECK_FALSE(run.succeeded());
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text == "out\nerr\n");
    CHECK(runExternal("sh", {"-c", "pwd > here.txt"}, work.path(), log, 30.0, "hint").succeeded());
    CHECK(std::filesystem::exists(work.path() / "here.txt"));  // it ran in the working folder
}

TEST_CASE("external process: the time limit kills a program that runs too long") {
    TemporaryDirectory work("rtlab-test-external");
    ExternalRun run = runExternal("sh", {"-c", "sleep 30"}, work.path(), work.path() / "log.txt", 0.3, "hint");
    CHECK(run.timedOut);
    CHECK_FALSE(run.succeeded());
    CHECK(run.exitStatus == 128 + 9);  // SIGKILL
    CHECK(run.seconds < 10.0);
}

TEST_CASE("external process: a program that is not there is one line naming the hint") {
    TemporaryDirectory work("rtlab-test-external");
    try {
        runExternal("/nonexistent/renderer", {}, work.path(), work.path() / "log.txt", 30.0,
                    "install it with scripts/install-deps");
        FAIL("started a program that does not exist");
    } catch (const Error& e) {
        std::string message = e.what();
        CHECK(message.find("cannot start /nonexistent/renderer") == 0);
        CHECK(message.find("(install it with scripts/install-deps)") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
}
