// The KD-tree's two reference builders (docs/a5-kdtree.md#building-in-on-log-n): the simple one,
// where every node sorts its own events, and Wald and Havran's O(N log N) one, which sorts once,
// must give the same tree bit for bit on every scene and option set; and the trees must end on
// inputs that no plane can split.
#include "framework/accel/primitive_set.h"
#include "framework/interface/a5_kdtree.h"
#include "grader/kit/test_scenes.h"

#include <doctest/doctest.h>

#include <functional>

using namespace rtlab;
using grader::SceneBuilder;

namespace {

struct NamedScene {
    std::string name;
    Scene scene;
};

std::vector<NamedScene> scenes() {
    std::vector<NamedScene> list;
    for (grader::TestScene& s : grader::hitSetScenes(RTLAB_BINARY_DIR "/models")) list.push_back({s.id, std::move(s.scene)});
    list.push_back({"stadium", grader::teapotInAStadium(RTLAB_BINARY_DIR "/models").scene});
    list.push_back({"flat", grader::flatScene().scene});  // zero width in z everywhere
    {
        SceneBuilder b;  // walls in the planes x = k and boxes between them: planar events everywhere
        for (int k = 0; k < 6; ++k) {
            b.addTriangle({float(k), 0, 0}, {float(k), 4, 0}, {float(k), 0, 4});
            b.addTriangle({k + 0.25f, 1, 1}, {k + 0.75f, 1, 1}, {k + 0.5f, 2, 2});
        }
        list.push_back({"walls", b.take()});
    }
    return list;
}

using Builder = std::function<KdTree(std::span<const Bounds3f>, const KdTreeOptions&)>;

// The depth of the deepest leaf, and whether every plane lies strictly inside its node's box.
void walkTree(const KdTree& tree, uint32_t index, const Bounds3f& box, int depth, int* deepest, bool* planesInside) {
    const KdNode& node = tree.nodes[index];
    if (node.isLeaf()) {
        *deepest = std::max(*deepest, depth);
        return;
    }
    int a = node.axis();
    *planesInside &= box.lower[a] < node.split() && node.split() < box.upper[a];
    Bounds3f below = box, above = box;
    below.upper[a] = above.lower[a] = node.split();
    walkTree(tree, index + 1, below, depth + 1, deepest, planesInside);
    walkTree(tree, node.aboveChild(), above, depth + 1, deepest, planesInside);
}

}  // namespace

TEST_CASE("the O(N log N) builder and the per-node sort build the same tree, bit for bit") {
    std::vector<KdTreeOptions> optionSets(4);
    optionSets[1].maxPrims = 4;
    optionSets[2].maxDepth = 40;
    optionSets[3].costs = KdCosts{5.0, 1.0, 0.8};
    for (NamedScene& named : scenes()) {
        PrimitiveSet primitives(named.scene);
        for (size_t k = 0; k < optionSets.size(); ++k) {
            CAPTURE(named.name);
            CAPTURE(k);
            KdTree sorted = buildKdTree(primitives.allBounds(), optionSets[k]);
            KdTree fast = buildKdTreeNlogN(primitives.allBounds(), optionSets[k]);
            CHECK(sorted.bounds == fast.bounds);
            CHECK(sorted.maxDepth == fast.maxDepth);
            CHECK(sorted.nodes.size() > 1);
            CHECK(sorted.nodes == fast.nodes);
            CHECK(sorted.primIndices == fast.primIndices);
            int deepest = 0;
            bool planesInside = true;
            walkTree(sorted, 0, sorted.bounds, 0, &deepest, &planesInside);
            CHECK(deepest <= sorted.maxDepth);
            CHECK(planesInside);
        }
    }
}

TEST_CASE("KD-tree builds end where no plane helps: identical, coplanar and no primitives") {
    for (const Builder& build : {Builder(buildKdTree), Builder(buildKdTreeNlogN)}) {
        SceneBuilder identical;  // no plane lies strictly inside their common box: one leaf
        for (int i = 0; i < 100; ++i) identical.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        PrimitiveSet same(identical.take());
        KdTree tree = build(same.allBounds(), KdTreeOptions{});
        REQUIRE(tree.nodes.size() == 1);
        CHECK(tree.nodes[0].primCount() == 100);

        SceneBuilder empty;
        PrimitiveSet none(empty.take());
        CHECK(build(none.allBounds(), KdTreeOptions{}).nodes.empty());
    }
}
