// A phase whose stub the worker holds exactly as committed is reported not started without
// running (grader/engine/worker_sources.h, sandbox.h's StubVerdicts); a filled-in file, a missing
// or malformed list of sources, or a phase that may call no stub runs as before.
#include "grader/a0_intersect/wire/intersection_inputs.h"
#include "grader/engine/assignment_registry.h"
#include "grader/engine/pristine_stubs.h"
#include "grader/engine/sandbox.h"
#include "grader/engine/worker_sources.h"
#include "grader/wire/task_inputs.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

using namespace rtlab::grader;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

const StubTable& a0() { return findAssignment("a0")->stubs(); }

// Every stub name of ray_box.cpp, the file these tests vary.
std::set<std::string> rayBoxStubs() {
    std::set<std::string> names;
    for (const StubFile& file : a0().files())
        if (file.file == "ray_box.cpp")
            for (const std::string& function : file.functions) names.insert(a0().name(function));
    return names;
}

struct Scratch {
    fs::path root = fs::temp_directory_path() / ("rtlab-worker-sources-" + std::to_string(::getpid()));
    std::string worker = (root / "worker").string();
    Scratch() { fs::remove_all(root); }
    ~Scratch() { fs::remove_all(root); }
};

}  // namespace

TEST_CASE("worker sources: only a file held exactly as committed names its stubs") {
    Scratch s;
    const std::map<std::string, std::string> committed = {{a0().path("ray_box.cpp"), "the committed stub\n"}};
    write(s.root / "src/a0_intersect/ray_box.cpp", "the committed stub\n");
    write(s.root / "src/a0_intersect/notes.h", "not a source\n");
    writeWorkerSources((s.root / "src").string(), s.worker);
    REQUIRE(!rayBoxStubs().empty());
    CHECK(unstartedStubs(committed, s.worker) == rayBoxStubs());
    // Unknown commits decide nothing.
    CHECK(unstartedStubs({}, s.worker).empty());

    write(s.root / "src/a0_intersect/ray_box.cpp", "the committed stub\n// started\n");
    writeWorkerSources((s.root / "src").string(), s.worker);
    CHECK(unstartedStubs(committed, s.worker).empty());

    // No list, a malformed one, or one larger than any build writes: every phase runs.
    fs::remove(workerSourcesPath(s.worker));
    CHECK(unstartedStubs(committed, s.worker).empty());
    write(workerSourcesPath(s.worker), "a0_intersect/ray_box.cpp\n\n \xff\n");
    CHECK(unstartedStubs(committed, s.worker).empty());
    write(s.root / "src/a0_intersect/ray_box.cpp", "the committed stub\n");
    writeWorkerSources((s.root / "src").string(), s.worker);
    std::string valid = read(workerSourcesPath(s.worker));
    write(workerSourcesPath(s.worker), valid + std::string(1 << 17, '#'));
    CHECK(unstartedStubs(committed, s.worker).empty());
}

TEST_CASE("worker sources: the build lists what each worker was built from") {
    const std::string source = RTLAB_SOURCE_DIR, binary = RTLAB_BINARY_DIR;
    const std::map<std::string, std::string> committed = committedStubs(source);
    REQUIRE(!committed.empty());
    // rtlab-worker holds assignments/: a stub is named exactly when its file there is as committed.
    std::set<std::string> expected;
    for (const Assignment& assignment : assignments()) {
        const StubTable& table = assignment.stubs();
        for (const StubFile& file : table.files())
            if (read(fs::path(source) / table.path(file.file)) == committed.at(table.path(file.file)))
                for (const std::string& function : file.functions) expected.insert(table.name(function));
    }
    CHECK(unstartedStubs(committed, binary + "/rtlab-worker") == expected);
    CHECK(unstartedStubs(committed, binary + "/rtlab-worker-solution").empty());
}

TEST_CASE("stub verdicts: a committed entry decides its phase without a worker") {
    Scratch s;
    const std::string entry = *rayBoxStubs().begin();
    StubVerdicts known({entry});
    // A worker that cannot start: any phase that runs fails.
    const WorkerSpec missing{(s.root / "no-such-worker").string(), SandboxLimits{}};
    const ChildPhase setUp{"the grader's set-up", worker::kTaskNone, {}, {}};
    const ChildPhase decided{entry, worker::kTaskBox, {1, 2, 3}, entry};

    SandboxRun run = runSandboxed(missing, std::vector<ChildPhase>{setUp, decided}, &known);
    REQUIRE(run.phases.size() == 2);
    CHECK(run.phases[0].status == PhaseStatus::Completed);
    CHECK(run.phases[1].status == PhaseStatus::NotStarted);
    CHECK(run.phases[1].reason == "not started: " + entry + " throws NotImplemented");
    CHECK(phasesToRun(std::vector<ChildPhase>{setUp, decided}, &known, SandboxLimits{}).empty());

    // A phase that may call no stub (a query with no rays) runs, whatever its label.
    ChildPhase mayCallNone = decided;
    mayCallNone.entry.clear();
    run = runSandboxed(missing, std::vector<ChildPhase>{setUp, mayCallNone}, &known);
    CHECK(run.phases[1].status != PhaseStatus::NotStarted);
    CHECK(phasesToRun(std::vector<ChildPhase>{setUp, mayCallNone}, &known, SandboxLimits{}) == std::vector<size_t>{0, 1});

    // A set-up not started still runs when a later phase does, as a worker goes on after it.
    ChildPhase decidedSetUp = decided;
    CHECK(phasesToRun(std::vector<ChildPhase>{decidedSetUp, mayCallNone}, &known, SandboxLimits{}) == std::vector<size_t>{0, 1});
    CHECK(phasesToRun(std::vector<ChildPhase>{decidedSetUp, decided}, &known, SandboxLimits{}).empty());
}
