// A worker started ahead of its phases (grader/engine/sandbox.h, StartedWorker) answers them
// exactly as a worker started for them does, and one dropped unused leaves no process behind.
#include "grader/a0_intersect/wire/intersection_inputs.h"
#include "grader/engine/sandbox.h"
#include "grader/wire/task_inputs.h"

#include <doctest/doctest.h>

#include <cerrno>
#include <sys/wait.h>

using namespace rtlab;
using namespace rtlab::grader;

namespace {

WorkerSpec solutionWorker() { return {std::string(RTLAB_BINARY_DIR) + "/rtlab-worker-solution", SandboxLimits{}}; }

// A set-up and a query phase of 200,000 slab tests: 8 MB of input, many pipe-fulls.
std::vector<ChildPhase> boxPhases() {
    std::vector<worker::BoxQuery> queries;
    for (int i = 0; i < 200000; ++i) {
        float x = float(i % 1000) / 500.0f - 1.0f;
        queries.push_back({Bounds3f(Vec3(-0.5f), Vec3(0.5f)), Ray{Vec3(x, 0.25f, -5.0f), Vec3(0, 0, 1), 0.0f, 100.0f}});
    }
    ByteWriter input;
    input.putVector(queries);
    return {ChildPhase{"set-up", worker::kTaskNone, {}, {}}, ChildPhase{"a0 intersectBox", worker::kTaskBox, input.bytes(), "a0 intersectBox"}};
}

bool noChildLeft() {
    errno = 0;
    return waitpid(-1, nullptr, WNOHANG) == -1 && errno == ECHILD;
}

}  // namespace

TEST_CASE("started worker: answers its phases byte for byte as a worker started for them") {
    std::vector<ChildPhase> phases = boxPhases();
    SandboxRun fresh = runSandboxed(solutionWorker(), phases);
    SandboxRun ahead = runSandboxed(solutionWorker(), phases, nullptr, StartedWorker(solutionWorker(), phases));
    REQUIRE(fresh.phases.size() == 2);
    REQUIRE(ahead.phases.size() == 2);
    for (size_t k = 0; k < 2; ++k) {
        CAPTURE(k);
        CHECK(fresh.phases[k].status == PhaseStatus::Completed);
        CHECK(ahead.phases[k].status == PhaseStatus::Completed);
        CHECK(fresh.phases[k].data == ahead.phases[k].data);
    }
    // A hit byte and the entry distance per query; the rays with |x| <= 0.5 touch the box
    // (501 of every 1000, the two on its faces included).
    REQUIRE(ahead.phases[1].data.size() == 200000 * 5);
    size_t hits = 0;
    for (size_t q = 0; q < 200000; ++q) hits += ahead.phases[1].data[q * 5];
    CHECK(hits == 200 * 501);
    CHECK(noChildLeft());
}

TEST_CASE("started worker: dropped unused, it is killed and reaped") {
    std::vector<ChildPhase> phases = boxPhases();
    { StartedWorker unused(solutionWorker(), phases); }
    CHECK(noChildLeft());
    std::optional<StartedWorker> replaced(std::in_place, solutionWorker(), phases);
    *replaced = StartedWorker(solutionWorker(), phases);
    replaced.reset();
    CHECK(noChildLeft());
}
