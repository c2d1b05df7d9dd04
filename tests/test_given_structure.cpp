// The grader's structures for the given-structure queries and their judge (grader/
// given_structure.h): every correct traversal, whatever variant and whatever key, follows them;
// a traversal that answers for the scene does not; and the wire form refuses what cannot be
// walked safely.
#include "framework/accel/primitive_set.h"
#include "framework/interface/a1_bvh.h"
#include "framework/interface/a3_grid.h"
#include "framework/interface/a4_octree.h"
#include "framework/interface/a5_kdtree.h"
#include "framework/oracle/oracle.h"
#include "grader/a1_bvh/given_bvh.h"
#include "grader/a1_bvh/wire/bvh_codec.h"
#include "grader/a3_grid/given_grid.h"
#include "grader/a3_grid/wire/grid_codec.h"
#include "grader/a4_octree/given_octree.h"
#include "grader/a4_octree/wire/octree_codec.h"
#include "grader/a5_kdtree/given_kdtree.h"
#include "grader/a5_kdtree/wire/kdtree_codec.h"
#include "grader/kit/accelerator_checks.h"

#include <doctest/doctest.h>

#include <functional>
#include <set>

using namespace rtlab;
using namespace rtlab::grader;

namespace {

// A closest-hit and an any-hit traversal over the decoded structure.
struct Walker {
    std::function<bool(Traversal&, Hit&)> closest;
    std::function<bool(Traversal&)> occluded;
};

using Decode = std::function<Walker(ByteReader&, uint32_t primCount)>;

struct Kind {
    const char* name;
    GivenStructure (*make)(const Scene&, uint64_t);
    Decode decode;
};

std::vector<Kind> kinds() {
    return {
        {"grid", givenGrid,
         [](ByteReader& in, uint32_t n) {
             auto grid = std::make_shared<UniformGrid>(readGrid(in, n));
             return Walker{[grid](Traversal& t, Hit& h) { return intersectGrid(*grid, t, h); }, [grid](Traversal& t) { return occludedGrid(*grid, t); }};
         }},
        {"octree", givenOctree,
         [](ByteReader& in, uint32_t n) {
             auto octree = std::make_shared<Octree>(readOctree(in, n));
             return Walker{[octree](Traversal& t, Hit& h) { return intersectOctree(*octree, t, h); },
                           [octree](Traversal& t) { return occludedOctree(*octree, t); }};
         }},
        {"kdtree", givenKdTree,
         [](ByteReader& in, uint32_t n) {
             auto tree = std::make_shared<KdTree>(readKdTree(in, n));
             return Walker{[tree](Traversal& t, Hit& h) { return intersectKdTree(*tree, t, h); }, [tree](Traversal& t) { return occludedKdTree(*tree, t); }};
         }},
        {"bvh", givenBvh,
         [](ByteReader& in, uint32_t n) {
             auto bvh = std::make_shared<Bvh>(readBvh(in, n));
             return Walker{[bvh](Traversal& t, Hit& h) { return intersectBvh(*bvh, t, h); }, [bvh](Traversal& t) { return occludedBvh(*bvh, t); }};
         }},
    };
}

// Another correct variant: every leaf the ray's segment meets, in list order, every primitive
// tested with the whole segment; no order, no early end, no mailbox.
Walker everyLeafWalker(const LeafList& leaves) {
    auto crossed = [&leaves](Traversal& t, size_t leaf, float tMax) {
        float tEnter;
        return t.hitsBox(leaves.boxes[leaf], tMax, &tEnter);
    };
    return Walker{[&leaves, crossed](Traversal& t, Hit& hit) {
                      for (size_t leaf = 0; leaf < leaves.prims.size(); ++leaf)
                          if (crossed(t, leaf, t.ray().tMax))
                              for (uint32_t p : leaves.prims[leaf]) t.intersect(p, hit);
                      return hit.found();
                  },
                  [&leaves, crossed](Traversal& t) {
                      for (size_t leaf = 0; leaf < leaves.prims.size(); ++leaf)
                          if (crossed(t, leaf, t.ray().tMax))
                              for (uint32_t p : leaves.prims[leaf])
                                  if (t.occludes(p)) return true;
                      return false;
                  }};
}

struct Problems {
    size_t wrong = 0, notHeld = 0;
    std::string first;
};

Problems judgeWalker(PreparedScene& scene, const GivenStructureJudge& judge, const Walker& walker) {
    PrimitiveSet primitives(scene.test.scene);
    Problems problems;
    auto note = [&](const std::string& problem) {
        if (problem.empty()) return;
        ++problems.wrong;
        problems.notHeld += problem.find(GivenStructureJudge::kNotInStructure) != std::string::npos;
        if (problems.first.empty()) problems.first = problem;
    };
    for (size_t i = 0; i < scene.rays.rays.size(); ++i) {
        TraversalStats stats;
        const Ray& ray = scene.rays.rays[i];
        Traversal closest(primitives, ray, stats);
        Hit hit;
        hit.t = ray.tMax;
        bool found = walker.closest(closest, hit);
        note(judge.judgeClosest(*scene.judge, i, ray, HitAnswer{found ? hit.prim : kNoHit, hit.t}));
        Traversal anyHit(primitives, scene.anyHitRays[i], stats);
        note(judge.judgeOccluded(*scene.anyHitJudge, i, scene.anyHitRays[i], walker.occluded(anyHit)));
    }
    return problems;
}

std::vector<std::shared_ptr<PreparedScene>> scenes() {
    return {prepareScene(icosphere(2), 7), prepareScene(triangleSoup(800, 3), 7), prepareScene(cornellBox(), 7)};
}

}  // namespace

TEST_CASE("given structures: the reference traversals and a variant without order or early end follow them, for every key") {
    auto prepared = scenes();
    for (const Kind& kind : kinds())
        for (auto& scene : prepared)
            for (uint64_t key : {1ull, 2ull, 0x9e3779b97f4a7c15ull, 12345678901ull}) {
                CAPTURE(kind.name);
                CAPTURE(scene->test.id);
                CAPTURE(key);
                GivenStructure given = kind.make(scene->test.scene, key);
                ByteReader in(given.encoded);
                Walker reference = kind.decode(in, scene->test.scene.primitiveCount());
                CHECK(in.atEnd());
                GivenStructureJudge judge(given.leaves, scene->test.scene);
                Problems problems = judgeWalker(*scene, judge, reference);
                CAPTURE(problems.first);
                CHECK(problems.wrong == 0);
                problems = judgeWalker(*scene, judge, everyLeafWalker(given.leaves));
                CAPTURE(problems.first);
                CHECK(problems.wrong == 0);
            }
}

TEST_CASE("given structures: a traversal that answers for the scene, not the structure, is told apart on every scene") {
    for (auto& scene : scenes()) {
        Oracle oracle(scene->test.scene);
        Walker sceneAnswers{[&](Traversal& t, Hit& hit) {
                                OracleHit h = oracle.closestHit(OracleRay::from(t.ray()));
                                if (h.hit) {
                                    hit.t = float(h.t);
                                    hit.prim = h.prim;
                                }
                                return h.hit;
                            },
                            [&](Traversal& t) { return oracle.anyHit(OracleRay::from(t.ray())); }};
        for (const Kind& kind : kinds()) {
            CAPTURE(kind.name);
            CAPTURE(scene->test.id);
            GivenStructure given = kind.make(scene->test.scene, 77);
            GivenStructureJudge judge(given.leaves, scene->test.scene);
            Problems problems = judgeWalker(*scene, judge, sceneAnswers);
            // Far more than the grader's threshold for "does not follow its structure" (3 rays).
            CHECK(problems.notHeld >= 30);
        }
    }
}

TEST_CASE("leaveOut: about a tenth of the primitives gone from every leaf, the same for the same key, leaves kept filled on request") {
    auto scene = prepareScene(triangleSoup(2000, 5), 1);
    GivenStructure a = givenGrid(scene->test.scene, 42), b = givenGrid(scene->test.scene, 42), c = givenGrid(scene->test.scene, 43);
    CHECK(a.encoded == b.encoded);
    CHECK(a.encoded != c.encoded);
    std::vector<size_t> references(scene->test.scene.primitiveCount());
    for (const auto& list : a.leaves.prims)
        for (uint32_t p : list) ++references[p];
    size_t gone = 0;
    for (size_t n : references) gone += n == 0;
    double share = double(gone) / double(references.size());
    CHECK(share > 0.07);
    CHECK(share < 0.13);

    LeafList leaves{{Bounds3f(Vec3(0), Vec3(1)), Bounds3f(Vec3(1), Vec3(2))}, {{0, 1, 2}, {3}}};
    for (uint64_t key = 0; key < 200; ++key) {
        LeafList kept = leaves;
        leaveOut(kept, 4, key, true);
        for (const auto& list : kept.prims) CHECK_FALSE(list.empty());
    }
}

TEST_CASE("structure codec: what cannot be walked safely is refused") {
    auto refuses = [](const std::function<void(ByteWriter&)>& write, const std::function<void(ByteReader&)>& read) {
        ByteWriter out;
        write(out);
        ByteReader in(out.bytes());
        CHECK_THROWS_AS(read(in), WireError);
    };
    UniformGrid grid;
    grid.resolution = {2, 1, 1};
    grid.cellStart = {0, 2, 1};  // decreasing
    grid.primIndices = {0};
    refuses([&](ByteWriter& out) { writeGrid(out, grid); }, [](ByteReader& in) { readGrid(in, 4); });
    grid.cellStart = {0, 1, 1};
    grid.primIndices = {9};  // out of range
    refuses([&](ByteWriter& out) { writeGrid(out, grid); }, [](ByteReader& in) { readGrid(in, 4); });

    Octree octree;
    octree.nodes.resize(9);
    octree.nodes[0].firstChild = 0;  // a leaf: fine; now a child link back to itself
    octree.nodes[1].firstChild = 1;
    refuses([&](ByteWriter& out) { writeOctree(out, octree); }, [](ByteReader& in) { readOctree(in, 4); });

    KdTree tree;
    tree.maxDepth = 4;
    tree.nodes = {KdNode::interior(0, 0.5f, 1), KdNode::leaf(0, 0)};  // above child not after the below one
    refuses([&](ByteWriter& out) { writeKdTree(out, tree); }, [](ByteReader& in) { readKdTree(in, 4); });
    tree.nodes = {KdNode::interior(0, 0.5f, 2), KdNode::leaf(0, 0), KdNode::leaf(0, 3)};  // range beyond the list
    refuses([&](ByteWriter& out) { writeKdTree(out, tree); }, [](ByteReader& in) { readKdTree(in, 4); });
    tree.maxDepth = 0;  // deeper than its limit
    tree.nodes = {KdNode::interior(0, 0.5f, 2), KdNode::leaf(0, 0), KdNode::leaf(0, 0)};
    refuses([&](ByteWriter& out) { writeKdTree(out, tree); }, [](ByteReader& in) { readKdTree(in, 4); });

    Bvh bvh;
    bvh.nodes.resize(2);
    bvh.nodes[0].offset = 0;  // interior (primCount 0) whose second child is itself
    refuses([&](ByteWriter& out) { writeBvh(out, bvh); }, [](ByteReader& in) { readBvh(in, 4); });
}
