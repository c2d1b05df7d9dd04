#include "grader/engine/failed_case_traces.h"

#include "framework/accel/traversal_trace_format.h"
#include "grader/engine/test_group.h"
#include "grader/wire/scene_codec.h"
#include "grader/wire/task_inputs.h"

#include <cstring>

namespace rtlab::grader {
namespace {

// The stub a trace phase names in the sandbox's reasons: the walk runs the student's build and
// traversal, whichever the registry name calls.
constexpr const char* kTraceStub = "the traversal traced for the report's viewer";

// The rays of a case that need a trace: those without one (a visit-order case has its list).
std::vector<size_t> raysToTrace(const FailedCase& failed) {
    std::vector<size_t> indices;
    for (size_t k = 0; k < failed.rays.size(); ++k)
        if (!failed.rays[k].studentTrace && failed.rays[k].student.kind != CaseAnswer::Kind::None) indices.push_back(k);
    return indices;
}

ChildPhase tracePhase(const FailedCase& failed, const std::vector<size_t>& indices) {
    ByteWriter input;
    writeScene(*failed.scene, input);
    worker::TraceRequest request{};
    std::strncpy(request.accelerator, failed.traceAccelerator.c_str(), sizeof request.accelerator - 1);
    input.put(request);
    std::vector<Ray> rays;
    std::vector<uint8_t> anyHit;
    for (size_t k : indices) {
        rays.push_back(failed.rays[k].ray);
        anyHit.push_back(failed.rays[k].student.kind == CaseAnswer::Kind::AnyHit ? 1 : 0);
    }
    input.putVector(rays);
    input.putVector(anyHit);
    return makePhase(kTraceStub, worker::kTaskTraceRays, std::move(input));
}

// The traces a phase sent, each decoded as untrusted data; a problem becomes a note.
void readTraces(const PhaseOutcome& outcome, const std::vector<size_t>& indices, FailedCase& failed) {
    if (outcome.status != PhaseStatus::Completed) {
        failed.notes.push_back("no trace of your walk: " + outcome.reason);
        return;
    }
    try {
        ByteReader in(outcome.data);
        for (size_t k : indices) {
            std::vector<uint8_t> bytes = in.getVector<uint8_t>(worker::kMaxTraceBytes);
            failed.rays[k].studentTrace = decodeTraversalTrace(bytes, worker::kMaxTraceOps);
        }
    } catch (const std::exception& e) {  // WireError, TraceFormatError
        for (size_t k : indices) failed.rays[k].studentTrace.reset();
        failed.notes.push_back(std::string("no trace of your walk: the worker sent a malformed one: ") + e.what());
    }
}

}  // namespace

void recordStudentTraces(std::vector<TestResult>& tests, const WorkerSpec& worker) {
    std::vector<ChildPhase> phases;
    std::vector<std::pair<FailedCase*, std::vector<size_t>>> traced;
    for (TestResult& test : tests) {
        if (test.status != TestStatus::Failed) continue;
        for (FailedCase& failed : test.failedCases) {
            if (failed.traceAccelerator.empty() || !failed.scene) continue;
            if (failed.traceAccelerator.size() >= sizeof worker::TraceRequest::accelerator) {
                failed.notes.push_back("no trace of your walk: the structure's name " + failed.traceAccelerator + " is too long to send");
                continue;
            }
            std::vector<size_t> indices = raysToTrace(failed);
            if (indices.empty()) continue;
            phases.push_back(tracePhase(failed, indices));
            traced.emplace_back(&failed, std::move(indices));
        }
    }
    if (phases.empty()) return;
    SandboxRun run = runSandboxed(worker, phases);
    for (size_t p = 0; p < traced.size() && p < run.phases.size(); ++p) readTraces(run.phases[p], traced[p].second, *traced[p].first);
}

}  // namespace rtlab::grader
