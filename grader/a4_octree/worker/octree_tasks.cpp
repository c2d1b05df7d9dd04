// a4's functions on the grader's inputs: the boxes, the triangle-box test, the pieces of the
// walk, a whole build and traversals of the octree that build produced (those two through the
// octree's adapter, as the accelerator builds and queries it).
#include "framework/accel/octree/octree_adapter.h"
#include "framework/interface/a4_octree.h"
#include "grader/wire/scene_codec.h"
#include "grader/a4_octree/wire/octree_codec.h"
#include "grader/a4_octree/wire/octree_inputs.h"
#include "grader/worker/structure_queries.h"
#include "grader/worker/worker_tasks.h"

namespace rtlab::grader::worker {
namespace {

constexpr uint64_t kMaxCalls = uint64_t(1) << 20;
constexpr uint64_t kMaxRays = uint64_t(1) << 24;

void runRootBox(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const Bounds3f& bounds : input.getVector<Bounds3f>(kMaxCalls)) output.put(octreeRootBox(bounds));
}

void runChildBox(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const ChildBoxCall& call : input.getVector<ChildBoxCall>(kMaxCalls)) {
        if (call.child < 0 || call.child >= kOctreeChildren) throw WireError("bad child index");
        output.put(childBox(call.box, call.child));
    }
}

void runChildIndex(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const ChildIndexCall& call : input.getVector<ChildIndexCall>(kMaxCalls)) output.put<int32_t>(childIndex(call.p, call.mid));
}

void runTriangleBox(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const TriangleBoxCall& call : input.getVector<TriangleBoxCall>(kMaxCalls))
        output.put<uint8_t>(triangleOverlapsBox(call.p0, call.p1, call.p2, call.box) ? 1 : 0);
}

void runMirror(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto root = input.get<Bounds3f>();
    for (const Ray& ray : input.getVector<Ray>(kMaxCalls)) output.put(mirrorRay(root, ray));
}

void runRootSpan(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto root = input.get<Bounds3f>();
    for (const Ray& ray : input.getVector<Ray>(kMaxCalls)) output.put(rootSpan(root, ray));
}

void runMid(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const MidCall& call : input.getVector<MidCall>(kMaxCalls)) output.put(midParameters(call.mirrored, call.span, call.box));
}

void runFirstNode(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const FirstNodeCall& call : input.getVector<FirstNodeCall>(kMaxCalls)) output.put<int32_t>(firstNode(call.t0, call.tm));
}

void runNextNode(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const NextNodeCall& call : input.getVector<NextNodeCall>(kMaxCalls)) {
        if (call.current < 0 || call.current >= kOctreeChildren) throw WireError("bad child index");
        output.put<int32_t>(nextNode(call.current, call.t1));
    }
}

void runBuild(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto options = input.get<OctreeOptions>();
    if (options.maxPrims < 1 || options.maxPrims > 65535 || options.maxDepth < 0 || options.maxDepth > 20 ||
        (options.insertion != OctreeInsertion::Exact && options.insertion != OctreeInsertion::Box))
        throw WireError("bad octree options");
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    Octree& octree = state.structure.emplace<Octree>();  // queries after a build that threw see an empty octree
    octree = OctreeAdapter::build(*state.primitives, options);
    writeOctree(output, octree);
}

// The visit-order test judges these lists: the leaves in the order the walk entered them.
void runLeaves(ByteReader& input, ByteWriter& output, WorkerState& state) {
    const Octree& octree = builtStructure<Octree>(state);
    writeListsPerRay(
        *state.primitives, input.getVector<Ray>(kMaxRays), kMaxListedLeaves, output,
        [](Traversal& t, std::vector<uint32_t>* list) { t.listLeavesIn(list); }, [&](Traversal& t, Hit& hit) { OctreeAdapter::intersect(octree, t, hit); });
}

const TaskRegistration registration{{kTaskOctreeRootBox, runRootBox},     {kTaskOctreeChildBox, runChildBox},
                                    {kTaskOctreeChildIndex, runChildIndex}, {kTaskTriangleBox, runTriangleBox},
                                    {kTaskOctreeMirror, runMirror},         {kTaskOctreeRootSpan, runRootSpan},
                                    {kTaskOctreeMid, runMid},               {kTaskOctreeFirstNode, runFirstNode},
                                    {kTaskOctreeNextNode, runNextNode},     {kTaskOctreeBuild, runBuild},
                                    {kTaskOctreeLeaves, runLeaves},
                                    {kTaskOctreeQuery, runBuiltQuery<OctreeAdapter, Octree>},
                                    {kTaskOctreeGivenQuery, runGivenQuery<OctreeAdapter, readOctree>}};

}  // namespace

}  // namespace rtlab::grader::worker
