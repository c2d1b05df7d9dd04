#include "grader/engine/test_group.h"

#include "grader/wire/task_inputs.h"

namespace rtlab::grader {

ChildPhase noSetUp() {
    return ChildPhase{"the grader's set-up", worker::kTaskNone, {}, {}};
}

ChildPhase makePhase(std::string stub, std::string task, ByteWriter input) {
    std::string entry = stub;
    return makePhase(std::move(stub), std::move(task), std::move(input), std::move(entry));
}

ChildPhase makePhase(std::string stub, std::string task, ByteWriter input, std::string entry) {
    return ChildPhase{std::move(stub), std::move(task), std::move(input.bytes()), std::move(entry)};
}

bool failedPhaseResult(const PhaseOutcome& outcome, TestResult& result) {
    result.seconds += outcome.seconds;
    if (outcome.status == PhaseStatus::Completed) return false;
    result.status = outcome.status == PhaseStatus::NotStarted ? TestStatus::NotStarted : TestStatus::Failed;
    result.fraction = 0.0;
    result.reason = outcome.reason;
    return true;
}

void requireFollowedStructure(const GradingContext& context, TestResult& result) {
    auto it = context.unfollowedStructure.find(result.assignment);
    if (it == context.unfollowedStructure.end() || result.status != TestStatus::Passed) return;
    result.status = TestStatus::Failed;
    result.fraction = 0.0;
    result.reason = "not credited: the traversal does not follow the structure it is given, so these answers may come from another: " + it->second;
}

TestResult makeResult(const std::string& assignment, const std::string& name) {
    TestResult result;
    result.assignment = assignment;
    result.name = name;
    return result;
}

}  // namespace rtlab::grader
