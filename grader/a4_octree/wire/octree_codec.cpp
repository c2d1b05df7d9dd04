#include "grader/a4_octree/wire/octree_codec.h"

#include "grader/wire/index_checks.h"

namespace rtlab::grader {

void writeOctree(ByteWriter& out, const Octree& octree) {
    out.put(octree.root);
    out.putVector(octree.nodes);
    out.putVector(octree.primIndices);
}

Octree readOctree(ByteReader& in, uint32_t primCount) {
    Octree octree;
    octree.root = in.get<Bounds3f>();
    octree.nodes = in.getVector<OctreeNode>(kMaxStructureEntries);
    octree.primIndices = in.getVector<uint32_t>(kMaxStructureEntries);
    if (octree.nodes.empty()) throw WireError("an octree without a root");
    for (size_t i = 0; i < octree.nodes.size(); ++i) {
        const OctreeNode& node = octree.nodes[i];
        if (node.isLeaf()) checkLeafRange(node.primStart, node.primCount, octree.primIndices.size());
        else if (node.firstChild <= i || node.firstChild > octree.nodes.size() - kOctreeChildren) throw WireError("a child link out of order");
    }
    checkPrimitiveIds(octree.primIndices, primCount);
    return octree;
}

}  // namespace rtlab::grader
