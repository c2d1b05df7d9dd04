// The student's walk of a few rays, for the report's viewer pages (docs/viewer.md#from-the-report):
// the structure the registry name builds with the student's code, each ray traced through it
// with the traversal context recording its counted operations, capped at kMaxTraceOps.
#include "framework/accel/accelerator.h"
#include "framework/accel/traversal_trace_format.h"
#include "framework/interface/traversal_stats.h"
#include "grader/wire/scene_codec.h"
#include "grader/wire/task_inputs.h"
#include "grader/worker/worker_tasks.h"

#include <algorithm>

namespace rtlab::grader::worker {
namespace {

void runTraceRays(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto request = input.get<TraceRequest>();
    if (std::find(request.accelerator, request.accelerator + sizeof request.accelerator, '\0') ==
        request.accelerator + sizeof request.accelerator)
        throw WireError("an accelerator name without its end");
    auto rays = input.getVector<Ray>(256);
    auto anyHit = input.getVector<uint8_t>(256);
    if (anyHit.size() != rays.size()) throw WireError("one query kind per ray");
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    std::unique_ptr<Accelerator> accelerator = makeAccelerator(AcceleratorSpec{request.accelerator});
    accelerator->build(*state.primitives);
    for (size_t k = 0; k < rays.size(); ++k) {
        TraversalTrace trace;
        trace.capacity = kMaxTraceOps;
        TraversalStats stats;
        stats.trace = &trace;
        if (anyHit[k]) accelerator->occluded(rays[k], stats);
        else accelerator->intersect(rays[k], stats);
        output.putVector(encodeTraversalTrace(trace));
    }
}

const TaskRegistration registration{{kTaskTraceRays, runTraceRays}};

}  // namespace

}  // namespace rtlab::grader::worker
