// The query tasks every graded structure has, through its adapter
// (framework/accel/<structure>/<structure>_adapter.h): closest hit or any hit for the request's
// rays, on the structure the build made, or on one the grader built and sent
// (grader/kit/given_structure.h), which the traversal must follow.
#pragma once

#include "framework/interface/traversal.h"
#include "grader/worker/query_answers.h"
#include "grader/worker/worker_tasks.h"

namespace rtlab::grader::worker {

template <typename Adapter, typename Structure>
void answerQueries(const Structure& structure, const PrimitiveSet& primitives, ByteReader& input, ByteWriter& output) {
    QueryRequest request = readQueryRequest(input);
    output.putVector(answerRays(
        primitives, request.rays, request.kind == QueryKind::Occluded, [&](Traversal& t) { return Adapter::occluded(structure, t); },
        [&](Traversal& t, Hit& hit) { return Adapter::intersect(structure, t, hit); }));
}

// The task on the structure the build phase made.
template <typename Adapter, typename Structure>
void runBuiltQuery(ByteReader& input, ByteWriter& output, WorkerState& state) {
    answerQueries<Adapter>(builtStructure<Structure>(state), *state.primitives, input, output);
}

// The task on the structure that comes first in its input, decoded by readStructure(input,
// primitive count), over the primitives of the last build.
template <typename Adapter, auto readStructure>
void runGivenQuery(ByteReader& input, ByteWriter& output, WorkerState& state) {
    const PrimitiveSet& primitives = builtPrimitives(state);
    answerQueries<Adapter>(readStructure(input, primitives.size()), primitives, input, output);
}

}  // namespace rtlab::grader::worker
