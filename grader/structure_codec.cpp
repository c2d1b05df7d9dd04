#include "grader/structure_codec.h"

#include "grader/worker/grid_inputs.h"
#include "grader/worker/kdtree_inputs.h"

#include <algorithm>

namespace rtlab::grader {
namespace {

// Larger than any structure the graded scenes give (a 64^3 grid holds 262,145 cell starts).
constexpr uint64_t kMaxEntries = uint64_t(1) << 26;
constexpr int32_t kMaxGridResolution = 1024;

void checkPrims(const std::vector<uint32_t>& prims, uint32_t primCount) {
    for (uint32_t p : prims)
        if (p >= primCount) throw WireError("a primitive id out of range");
}

void checkRange(uint64_t start, uint64_t count, size_t size) {
    if (start > size || count > size - start) throw WireError("a leaf's range beyond the primitive list");
}

}  // namespace

void writeGrid(ByteWriter& out, const UniformGrid& grid) {
    out.put(worker::GridFrame{grid.bounds, grid.resolution, grid.cellWidth, grid.inverseWidth});
    out.putVector(grid.cellStart);
    out.putVector(grid.primIndices);
}

UniformGrid readGrid(ByteReader& in, uint32_t primCount) {
    auto frame = in.get<worker::GridFrame>();
    UniformGrid grid;
    for (int a = 0; a < 3; ++a)
        if (frame.resolution[a] < 1 || frame.resolution[a] > kMaxGridResolution) throw WireError("bad grid resolution");
    grid.bounds = frame.bounds;
    grid.resolution = frame.resolution;
    grid.cellWidth = frame.cellWidth;
    grid.inverseWidth = frame.inverseWidth;
    grid.cellStart = in.getVector<uint32_t>(kMaxEntries);
    grid.primIndices = in.getVector<uint32_t>(kMaxEntries);
    if (grid.cellStart.size() != grid.cellCount() + 1 || grid.cellStart.front() != 0 || grid.cellStart.back() != grid.primIndices.size() ||
        !std::is_sorted(grid.cellStart.begin(), grid.cellStart.end()))
        throw WireError("malformed cell starts");
    checkPrims(grid.primIndices, primCount);
    return grid;
}

void writeOctree(ByteWriter& out, const Octree& octree) {
    out.put(octree.root);
    out.putVector(octree.nodes);
    out.putVector(octree.primIndices);
}

Octree readOctree(ByteReader& in, uint32_t primCount) {
    Octree octree;
    octree.root = in.get<Bounds3f>();
    octree.nodes = in.getVector<OctreeNode>(kMaxEntries);
    octree.primIndices = in.getVector<uint32_t>(kMaxEntries);
    if (octree.nodes.empty()) throw WireError("an octree without a root");
    for (size_t i = 0; i < octree.nodes.size(); ++i) {
        const OctreeNode& node = octree.nodes[i];
        if (node.isLeaf()) checkRange(node.primStart, node.primCount, octree.primIndices.size());
        else if (node.firstChild <= i || node.firstChild > octree.nodes.size() - kOctreeChildren) throw WireError("a child link out of order");
    }
    checkPrims(octree.primIndices, primCount);
    return octree;
}

void writeKdTree(ByteWriter& out, const KdTree& tree) {
    out.put(worker::KdTreeFrame{tree.bounds, tree.maxDepth});
    out.putVector(tree.nodes);
    out.putVector(tree.primIndices);
}

KdTree readKdTree(ByteReader& in, uint32_t primCount) {
    KdTree tree;
    auto frame = in.get<worker::KdTreeFrame>();
    tree.bounds = frame.bounds;
    tree.maxDepth = frame.maxDepth;
    tree.nodes = in.getVector<KdNode>(kMaxEntries);
    tree.primIndices = in.getVector<uint32_t>(kMaxEntries);
    if (tree.maxDepth < 0 || tree.maxDepth > kKdMaxDepthLimit) throw WireError("bad KD-tree depth limit");
    // Below child next, above child later: every link points forward, and no node lies deeper
    // than the limit a traversal sizes its stack by.
    std::vector<int> depth(tree.nodes.size(), 0);
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        const KdNode& node = tree.nodes[i];
        if (depth[i] > tree.maxDepth) throw WireError("a KD-tree node below the depth limit");
        if (node.isLeaf()) {
            checkRange(node.firstPrim(), node.primCount(), tree.primIndices.size());
            continue;
        }
        if (node.axis() > 2 || i + 1 >= tree.nodes.size() || node.aboveChild() <= i + 1 || node.aboveChild() >= tree.nodes.size())
            throw WireError("a child link out of order");
        depth[i + 1] = depth[node.aboveChild()] = depth[i] + 1;
    }
    checkPrims(tree.primIndices, primCount);
    return tree;
}

void writeBvh(ByteWriter& out, const Bvh& bvh) {
    out.putVector(bvh.nodes);
    out.putVector(bvh.primIndices);
}

Bvh readBvh(ByteReader& in, uint32_t primCount) {
    Bvh bvh;
    bvh.nodes = in.getVector<BvhNode>(kMaxEntries);
    bvh.primIndices = in.getVector<uint32_t>(kMaxEntries);
    for (size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& node = bvh.nodes[i];
        if (node.isLeaf()) checkRange(node.offset, node.primCount, bvh.primIndices.size());
        else if (node.axis > 2 || i + 1 >= bvh.nodes.size() || node.offset <= i + 1 || node.offset >= bvh.nodes.size())
            throw WireError("a child link out of order");
    }
    checkPrims(bvh.primIndices, primCount);
    return bvh;
}

}  // namespace rtlab::grader
