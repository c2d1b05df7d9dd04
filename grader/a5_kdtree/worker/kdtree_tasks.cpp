// a5's functions on the grader's inputs: the plane cost, events, the best plane, classification,
// the leaf rule, the child order, a traversal of a tree the grader built by hand, a whole build
// and traversals of the tree it produced; and the optional BSP autopartition. Whole builds and
// traversals go through the structures' adapters, as the accelerators build and query them.
#include "framework/accel/bsp/bsp_adapter.h"
#include "framework/accel/kdtree/kdtree_adapter.h"
#include "framework/interface/a5_kdtree.h"
#include "grader/wire/scene_codec.h"
#include "grader/a5_kdtree/wire/kdtree_codec.h"
#include "grader/a5_kdtree/wire/kdtree_inputs.h"
#include "grader/worker/structure_queries.h"
#include "grader/worker/worker_tasks.h"

namespace rtlab::grader::worker {
namespace {

constexpr uint64_t kMaxCalls = uint64_t(1) << 16;
constexpr uint64_t kMaxItems = uint64_t(1) << 24;

void runKdSahCost(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const KdSahCall& c : input.getVector<KdSahCall>(kMaxCalls)) {
        if (c.axis < 0 || c.axis > 2) throw WireError("bad axis");
        output.put<double>(kdSahCost(c.node, c.axis, c.position, c.nBelow, c.nAbove, c.costs));
    }
}

void runKdEventOrder(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const KdEventPair& p : input.getVector<KdEventPair>(kMaxCalls)) output.put<uint8_t>(kdEventBefore(p.a, p.b) ? 1 : 0);
}

void runKdSortedEvents(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto cases = input.get<uint64_t>();
    if (cases > kMaxCalls) throw WireError("too many cases");
    for (uint64_t c = 0; c < cases; ++c) {
        auto boxes = input.getVector<Bounds3f>(kMaxItems);
        auto prims = input.getVector<uint32_t>(kMaxItems);
        auto axis = input.get<int32_t>();
        for (uint32_t prim : prims)
            if (prim >= boxes.size()) throw WireError("a primitive id out of range");
        if (axis < 0 || axis > 2) throw WireError("bad axis");
        output.putVector(kdSortedEvents(prims, boxes, axis));
    }
}

void runKdBestSplit(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto cases = input.get<uint64_t>();
    if (cases > kMaxCalls) throw WireError("too many cases");
    for (uint64_t c = 0; c < cases; ++c) {
        auto call = input.get<KdSplitCall>();
        std::array<std::vector<KdEvent>, 3> events;
        for (std::vector<KdEvent>& list : events) list = input.getVector<KdEvent>(kMaxItems);
        output.put(kdBestSplit(call.node, {events[0], events[1], events[2]}, call.primCount, call.costs));
    }
}

void runKdClassify(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const KdClassifyCall& c : input.getVector<KdClassifyCall>(kMaxCalls)) {
        if (c.axis < 0 || c.axis > 2) throw WireError("bad axis");
        output.put<uint8_t>(static_cast<uint8_t>(kdClassify(c.box, c.axis, c.position, c.planarSide)));
    }
}

void runKdMaxDepth(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (uint64_t n : input.getVector<uint64_t>(kMaxCalls)) output.put<int32_t>(kdMaxDepth(n));
}

void runKdDecide(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const KdDecideCall& c : input.getVector<KdDecideCall>(kMaxCalls))
        output.put(kdDecideNode(c.primCount, c.depth, c.best, c.badRefines, c.options));
}

void runKdChildOrder(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const KdChildOrderCall& c : input.getVector<KdChildOrderCall>(kMaxCalls)) {
        if (c.axis < 0 || c.axis > 2) throw WireError("bad axis");
        output.put(kdChildOrder(c.axis, c.split, c.ray, RayInverse(c.ray), c.tMin, c.tMax));
    }
}

// The student's traversal of a tree the grader made by hand (the traversal's truth table), with
// the primitives each closest-hit query tested, in order.
void runKdWalk(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    KdTree tree = readKdTree(input, state.primitives->size());
    auto query = static_cast<QueryKind>(input.get<uint8_t>());
    std::vector<uint32_t> tested;
    for (const Ray& ray : input.getVector<Ray>(kMaxCalls)) {
        TraversalStats stats;
        Traversal traversal(*state.primitives, ray, stats);
        tested.clear();
        traversal.listTestsIn(&tested);
        RawQuery answer{kNoHit, 0.0f, 0, 0};
        if (query == QueryKind::Occluded) {
            answer.prim = KdTreeAdapter::occluded(tree, traversal) ? 1 : 0;
        } else {
            Hit hit;
            hit.t = ray.tMax;
            answer.prim = KdTreeAdapter::intersect(tree, traversal, hit) ? hit.prim : kNoHit;
            answer.t = hit.t;
        }
        answer.nodeVisits = static_cast<uint32_t>(stats.steps());
        answer.primitiveTests = static_cast<uint32_t>(stats.primitiveTests);
        output.put(answer);
        auto n = static_cast<uint32_t>(std::min<size_t>(tested.size(), kMaxListedTests));
        output.put<uint32_t>(n);
        for (uint32_t i = 0; i < n; ++i) output.put<uint32_t>(tested[i]);
    }
}

void runKdBuild(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto options = input.get<KdTreeOptions>();
    auto function = static_cast<KdBuildFunction>(input.get<uint8_t>());
    if (options.maxPrims < 1 || options.maxDepth < 0 || options.maxDepth > kKdMaxDepthLimit) throw WireError("bad KD-tree options");
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    // An empty tree first: when the build throws, the query phases still reach the traversal
    // and report its own state (not started, or wrong on an empty tree).
    KdTree& tree = state.structure.emplace<KdTree>();
    tree = KdTreeAdapter::build(*state.primitives, options, function == KdBuildFunction::NlogN ? KdBuilder::NlogN : KdBuilder::Sort);
    writeKdTree(output, tree);
}

void runBspBuild(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto options = input.get<BspOptions>();
    if (options.maxPrims < 1 || options.maxDepth < 1 || options.maxDepth > kBspMaxDepthLimit) throw WireError("bad BSP options");
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    BspTree& tree = state.structure.emplace<BspTree>();  // as in runKdBuild
    tree = BspAdapter::build(*state.primitives, options);
    output.put<uint64_t>(tree.nodes.size());
    output.put<uint64_t>(tree.primIndices.size());
}

void runBspQuery(ByteReader& input, ByteWriter& output, WorkerState& state) {
    const BspTree& tree = builtStructure<BspTree>(state);
    auto query = static_cast<QueryKind>(input.get<uint8_t>());
    auto rays = input.getVector<Ray>(kMaxItems);
    output.putVector(answerRays(
        *state.primitives, rays, query == QueryKind::Occluded, [&](Traversal& t) { return BspAdapter::occluded(tree, t); },
        [&](Traversal& t, Hit& hit) { return BspAdapter::intersect(tree, t, hit); }));
}

const TaskRegistration registration{{kTaskKdSahCost, runKdSahCost},     {kTaskKdEventOrder, runKdEventOrder},
                                    {kTaskKdSortedEvents, runKdSortedEvents}, {kTaskKdBestSplit, runKdBestSplit},
                                    {kTaskKdClassify, runKdClassify},   {kTaskKdMaxDepth, runKdMaxDepth},
                                    {kTaskKdDecide, runKdDecide},       {kTaskKdChildOrder, runKdChildOrder},
                                    {kTaskKdWalk, runKdWalk},           {kTaskKdBuild, runKdBuild},
                                    {kTaskKdQuery, runBuiltQuery<KdTreeAdapter, KdTree>},
                                    {kTaskKdGivenQuery, runGivenQuery<KdTreeAdapter, readKdTree>},
                                    {kTaskBspBuild, runBspBuild},       {kTaskBspQuery, runBspQuery}};

}  // namespace

}  // namespace rtlab::grader::worker
