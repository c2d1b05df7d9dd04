// a1/a2's functions on the grader's inputs: split calls, a whole build, and traversals of the
// BVH that build produced.
#include "framework/accel/bvh_accelerator.h"
#include "framework/interface/traversal.h"
#include "framework/interface/a1_bvh.h"
#include "framework/interface/a2_sah.h"
#include "grader/scene_codec.h"
#include "grader/worker/task_inputs.h"
#include "grader/worker/worker_tasks.h"

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

}  // namespace

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
    state.bvh = buildBvh(buildPrimitivesOf(*state.primitives), options);
    output.putVector(state.bvh.nodes);
    output.putVector(state.bvh.primIndices);
}

void runBvhQuery(ByteReader& input, ByteWriter& output, WorkerState& state) {
    if (!state.primitives) throw WireError("a query before the build");
    auto query = static_cast<BvhQuery>(input.get<uint8_t>());
    auto rays = input.getVector<Ray>(kMaxPrimitives);
    std::vector<RawQuery> answers;
    answers.reserve(rays.size());
    for (const Ray& ray : rays) {
        TraversalStats stats;
        Traversal traversal(*state.primitives, ray, stats);
        RawQuery answer{kNoHit, 0.0f, 0, 0};
        if (query == BvhQuery::Occluded) {
            answer.prim = occludedBvh(state.bvh, traversal) ? 1 : 0;
        } else {
            Hit hit;
            hit.t = ray.tMax;
            bool found = query == BvhQuery::Ordered ? intersectBvh(state.bvh, traversal, hit) : intersectBvhRecursive(state.bvh, traversal, hit);
            answer.prim = found ? hit.prim : kNoHit;
            answer.t = hit.t;
        }
        answer.nodeVisits = static_cast<uint32_t>(stats.nodeVisits);
        answer.primitiveTests = static_cast<uint32_t>(stats.primitiveTests);
        answers.push_back(answer);
    }
    output.putVector(answers);
}

}  // namespace rtlab::grader::worker
