// The one way rtlab runs another program (framework/core/child_process.h): output captured up
// to its cap or logged, the exact environment, the resource limits, and a time limit that takes
// the child's whole group, and with killDescendants what left the group, along with it.
#include "framework/core/child_process.h"
#include "framework/external/temporary_directory.h"

#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

using namespace rtlab;

namespace {

ChildOptions shell(const std::string& script, double wallSeconds = 30.0) {
    ChildOptions options;
    options.argv = {"/bin/sh", "-c", script};
    options.wallSeconds = wallSeconds;
    return options;
}

// Whether a process still runs (a zombie waiting for its parent does not).
bool running(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) return false;
    size_t close = line.rfind(')');
    return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

bool endsSoon(pid_t pid) {
    for (int i = 0; i < 100 && running(pid); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return !running(pid);
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("child process: exit status, output captured up to its cap, the rest counted") {
    ChildRun run = runChild(shell("echo out; echo err >&2; exit 3"));
    CHECK(run.started);
    CHECK(run.exitCode == 3);
    CHECK_FALSE(run.succeeded());
    CHECK(run.output == "out\nerr\n");

    ChildOptions options = shell("head -c 100000 /dev/zero");
    options.captureBytes = 1000;
    run = runChild(options);
    CHECK(run.succeeded());
    CHECK(run.output.size() == 1000);
    CHECK(run.droppedBytes == 99000);
}

TEST_CASE("child process: exactly the environment given, in the folder given, stdin empty") {
    TemporaryDirectory work("rtlab-test-child");
    ChildOptions options = shell("echo \"$RTLAB_X|$HOME\"; pwd; cat");
    options.environment = std::vector<std::string>{"RTLAB_X=1"};
    options.workDir = work.path();
    ChildRun run = runChild(options);
    CHECK(run.succeeded());
    CHECK(run.output == "1|\n" + std::filesystem::canonical(work.path()).string() + "\n");
}

TEST_CASE("child process: a log file, truncated or appended to") {
    TemporaryDirectory work("rtlab-test-child");
    ChildOptions options = shell("echo one");
    options.logPath = work.path() / "log.txt";
    CHECK(runChild(options).succeeded());
    options.argv.back() = "echo two";
    options.appendLog = true;
    CHECK(runChild(options).succeeded());
    CHECK(readFile(options.logPath) == "one\ntwo\n");
    options.appendLog = false;
    CHECK(runChild(options).succeeded());
    CHECK(readFile(options.logPath) == "two\n");
}

TEST_CASE("child process: a program that cannot be run is not started, and says why") {
    ChildOptions options;
    options.argv = {"/nonexistent/program"};
    ChildRun run = runChild(options);
    CHECK_FALSE(run.started);
    CHECK(run.startError == "No such file or directory");
    options.argv = {"rtlab-no-such-program"};
    options.searchPath = true;
    CHECK_FALSE(runChild(options).started);
    options.argv = {"sh", "-c", "exit 0"};
    CHECK(runChild(options).succeeded());  // found on PATH
    options = shell("exit 0");
    options.workDir = "/nonexistent/folder";
    run = runChild(options);
    CHECK_FALSE(run.started);
    CHECK(run.startError == "No such file or directory");
}

TEST_CASE("child process: the time limit kills the child's whole group") {
    // The background sleep prints its pid and keeps the output open: the limit, not the output's
    // end, has to stop the wait.
    ChildRun run = runChild(shell("sleep 30 & echo $!; wait", 3.0));
    CHECK(run.timedOut);
    CHECK_FALSE(run.succeeded());
    CHECK(run.seconds < 10.0);
    REQUIRE(!run.output.empty());
    CHECK(endsSoon(std::stoi(run.output)));
}

TEST_CASE("child process: a child that exits while what it started holds the output open is stopped at the limit") {
    ChildRun run = runChild(shell("sleep 30 & exit 0", 1.0));
    CHECK(run.timedOut);
    CHECK_FALSE(run.succeeded());
    CHECK(run.seconds < 10.0);
}

TEST_CASE("child process: with killDescendants, also what left the group") {
    TemporaryDirectory work("rtlab-test-child");
    ChildOptions options = shell("setsid sleep 30 & echo $!; wait", 3.0);
    options.logPath = work.path() / "log.txt";
    options.killDescendants = true;
    ChildRun run = runChild(options);
    CHECK(run.timedOut);
    std::string pid = readFile(options.logPath);
    REQUIRE(!pid.empty());
    CHECK(endsSoon(std::stoi(pid)));
}

TEST_CASE("child process: the CPU limit ends a busy loop") {
    ChildOptions options = shell("while :; do :; done", 20.0);
    options.cpuSeconds = 1;
    options.noCoreDumps = true;
    ChildRun run = runChild(options);
    CHECK_FALSE(run.timedOut);
    CHECK((run.signal == SIGXCPU || run.signal == SIGKILL));
}
