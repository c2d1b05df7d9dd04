// A test group: the phases one sandboxed child runs (student code, raw results only) and the
// parent-side scoring that turns their raw results into test verdicts (docs/grading.md).
#pragma once

#include "grader/engine/reference_data.h"
#include "grader/engine/sandbox.h"
#include "grader/engine/test_result.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::grader {

inline constexpr uint64_t kDefaultSeed = 20260101;

struct PreparedScenes;  // bvh_tests.h: the hit-set scenes, shared by a1 and a2

// Everything a group needs from the grading run.
struct GradingContext {
    uint64_t seed = kDefaultSeed;
    std::string sourceDir;  // repository root: scenes/refs, grader/reference
    std::string modelsDir;  // where make models puts bunny.gltf
    std::string workDir;    // renders and heat maps for the HTML report
    ReferenceData reference;
    std::shared_ptr<PreparedScenes> scenes;  // built on first use
    // Which primitives the grader's own structures leave out of which leaves
    // (given_structure.h): drawn afresh for every grading run, never derived from the seed, so a
    // submission cannot know it in advance.
    uint64_t structureKey = 0;
    // Per assignment, why its traversal was found not to follow the structure it was given; the
    // tests whose answers a private structure could produce (images, degenerate inputs) read it.
    std::map<std::string, std::string> unfollowedStructure;
};

struct TestGroup {
    std::string assignment;  // "a0"
    std::string title;       // for progress lines
    std::vector<ChildPhase> phases;
    // Appends one TestResult per test of the group. Runs in the grader after the worker ended;
    // the worker never sees what it computes or the expected answers it captures.
    std::function<void(const SandboxRun&, std::vector<TestResult>&)> score;
};

// A phase 0 for groups whose tests need no shared set-up.
ChildPhase noSetUp();
// A phase that runs worker task `task` (grader/wire/task_inputs.h) on `input`, calling `stub`
// (one function, as StubTable::name names it) first.
ChildPhase makePhase(std::string stub, std::string task, ByteWriter input);
// The same, for a stub that names more than one function: the task calls `entry` first on
// every input (ChildPhase::entry); empty when it may call none.
ChildPhase makePhase(std::string stub, std::string task, ByteWriter input, std::string entry);

// The verdict for a test whose phase did not complete: "not started" for NotImplemented,
// otherwise failed with the sandbox's one-line reason. Returns false when the phase completed.
bool failedPhaseResult(const PhaseOutcome& outcome, TestResult& result);

// Fails a passed result when its assignment's traversal was found not to follow the structure
// it was given (GradingContext::unfollowedStructure): what it earned could come from another.
void requireFollowedStructure(const GradingContext& context, TestResult& result);

// A result named by its test with the assignment set; status failed until scored.
TestResult makeResult(const std::string& assignment, const std::string& name);

}  // namespace rtlab::grader
