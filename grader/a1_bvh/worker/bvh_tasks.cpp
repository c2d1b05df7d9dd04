// a1/a2's functions on the grader's inputs: split calls, a whole build, and traversals of the
// BVH that build produced (those two through the BVH's adapter, as the accelerator builds and
// queries it).
#include "framework/accel/bvh_adapter.h"
#include "framework/accel/bvh_layout.h"
#include "framework/interface/a1_bvh.h"
#include "framework/interface/a2_sah.h"
#include "grader/wire/scene_codec.h"
#include "grader/a1_bvh/wire/bvh_codec.h"
#include "grader/worker/query_answers.h"
#include "grader/a1_bvh/wire/bvh_inputs.h"
#include "grader/worker/worker_tasks.h"

#include <algorithm>

namespace rtlab::grader::worker {
namespace {

constexpr uint64_t kMaxCalls = 1 << 16;
constexpr uint64_t kMaxPrimitives = uint64_t(1) << 24;

uint32_t callSplit(const SplitCall& call, std::span<BuildPrimitive> prims) {
    NodeInfo node = describeNode(prims);
    switch (call.function) {
    case SplitFunction::Median: return splitMedian(prims, node);
    case SplitFunction::Middle: return splitMiddle(prims, node);
    case SplitFunction::EqualCounts: return splitEqualCounts(prims, node);
    case SplitFunction::SahSweep: return splitSahSweep(prims, node, call.options);
    case SplitFunction::SahBuckets: return splitSahBuckets(prims, node, call.options);
    }
    throw WireError("unknown split function");
}

// Each call's primitives are handed over in reverse order, so a function must really order
// them; the answer is k and the order the function left them in.
void runSplitCalls(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto calls = input.get<uint64_t>();
    if (calls > kMaxCalls) throw WireError("too many split calls");
    for (uint64_t c = 0; c < calls; ++c) {
        auto call = input.get<SplitCall>();
        auto boxes = input.getVector<Bounds3f>(kMaxPrimitives);
        std::vector<BuildPrimitive> prims;
        for (auto i = static_cast<uint32_t>(boxes.size()); i-- > 0;) prims.push_back(BuildPrimitive{boxes[i], boxes[i].centre(), i});
        output.put<uint32_t>(callSplit(call, prims));
        for (const BuildPrimitive& p : prims) output.put<uint32_t>(p.index);
    }
}

void runBvhBuild(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto options = input.get<BvhOptions>();
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    Bvh& bvh = state.structure.emplace<Bvh>();  // queries after a build that threw see an empty tree
    bvh = BvhAdapter::build(*state.primitives, options);
    writeBvh(output, bvh);
}

void answerBvhQueries(const Bvh& bvh, const PrimitiveSet& primitives, ByteReader& input, ByteWriter& output) {
    QueryRequest request = readQueryRequest(input);
    output.putVector(answerRays(
        primitives, request.rays, request.kind == QueryKind::Occluded, [&](Traversal& t) { return BvhAdapter::occluded(bvh, t); },
        [&](Traversal& t, Hit& hit) {
            return request.kind == QueryKind::Recursive ? BvhAdapter::intersectRecursive(bvh, t, hit) : BvhAdapter::intersect(bvh, t, hit);
        }));
}

// The tree the build phase made, once it is known to keep the layout a traversal relies on.
const Bvh& builtBvh(const WorkerState& state) {
    const Bvh& bvh = builtStructure<Bvh>(state);
    if (std::string problem = bvhLayoutProblem(bvh, state.primitives->size()); !problem.empty())
        throw PhaseNotRun("the tree the build made breaks the BVH layout (framework/interface/bvh.h): " + problem);
    return bvh;
}

void runBvhQuery(ByteReader& input, ByteWriter& output, WorkerState& state) {
    answerBvhQueries(builtBvh(state), *state.primitives, input, output);
}

// The traversal on a BVH the grader built (given_structure.h), not the one the build made.
void runBvhGivenQuery(ByteReader& input, ByteWriter& output, WorkerState& state) {
    const PrimitiveSet& primitives = builtPrimitives(state);
    answerBvhQueries(readBvh(input, primitives.size()), primitives, input, output);
}

// The ordered traversal again, listing the primitives it tests in order: the visit-order test
// judges which leaf comes first and whether a leaf is entered beyond the closest hit so far.
void runBvhVisits(ByteReader& input, ByteWriter& output, WorkerState& state) {
    const Bvh& bvh = builtBvh(state);
    writeListsPerRay(
        *state.primitives, input.getVector<Ray>(kMaxPrimitives), kMaxListedTests, output,
        [](Traversal& t, std::vector<uint32_t>* list) { t.listTestsIn(list); }, [&](Traversal& t, Hit& hit) { BvhAdapter::intersect(bvh, t, hit); });
}

const TaskRegistration registration{{kTaskSplit, runSplitCalls},
                                    {kTaskBvhBuild, runBvhBuild},
                                    {kTaskBvhQuery, runBvhQuery},
                                    {kTaskBvhGivenQuery, runBvhGivenQuery},
                                    {kTaskBvhVisits, runBvhVisits}};

}  // namespace

}  // namespace rtlab::grader::worker
