#include "grader/a1_bvh/wire/bvh_codec.h"

#include "grader/wire/index_checks.h"

namespace rtlab::grader {

void writeBvh(ByteWriter& out, const Bvh& bvh) {
    out.putVector(bvh.nodes);
    out.putVector(bvh.primIndices);
}

Bvh readBvh(ByteReader& in, uint32_t primCount) {
    Bvh bvh;
    bvh.nodes = in.getVector<BvhNode>(kMaxStructureEntries);
    bvh.primIndices = in.getVector<uint32_t>(kMaxStructureEntries);
    for (size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& node = bvh.nodes[i];
        if (node.isLeaf()) checkLeafRange(node.offset, node.primCount, bvh.primIndices.size());
        else if (node.axis > 2 || i + 1 >= bvh.nodes.size() || node.offset <= i + 1 || node.offset >= bvh.nodes.size())
            throw WireError("a child link out of order");
    }
    checkPrimitiveIds(bvh.primIndices, primCount);
    return bvh;
}

}  // namespace rtlab::grader
