#include "grader/a4_octree/octree_cases.h"

#include "grader/kit/stress_cases.h"
#include "grader/kit/test_scenes.h"

#include <limits>

namespace rtlab::grader {
namespace {

OctreeNode leaf(uint32_t primStart, uint32_t primCount) { return OctreeNode{0, primStart, primCount}; }
OctreeNode interior(uint32_t firstChild, uint32_t primCount) { return OctreeNode{firstChild, 0, primCount}; }

OctreeOptions options(uint32_t maxPrims, int maxDepth, OctreeInsertion insertion = OctreeInsertion::Exact) {
    OctreeOptions o;
    o.maxPrims = maxPrims;
    o.maxDepth = maxDepth;
    o.insertion = insertion;
    return o;
}

// The docs' worked example: triangle 0 in z = 0 near the origin, 1 in z = 1 near (1,1,1), 2 in
// the mid-plane z = 0.5 with its long edge on x + y = 0.5. The root is [0,1]^3.
Scene workedExample() {
    SceneBuilder b;
    b.addTriangle({0, 0, 0}, {0.25f, 0, 0}, {0, 0.25f, 0});
    b.addTriangle({1, 1, 1}, {0.75f, 1, 1}, {1, 0.75f, 1});
    b.addTriangle({0.125f, 0.125f, 0.5f}, {0.375f, 0.125f, 0.5f}, {0.125f, 0.375f, 0.5f});
    return b.take();
}

}  // namespace

std::vector<BuildCase> buildCases() {
    std::vector<BuildCase> cases;
    {
        // Root: 3 > maxPrims; 0 goes to child 0 only, 1 to child 7 only, 2 (in the mid-plane) to
        // children 0 and 1: no child gets all three, split (nodes 1..8). Node 1 ([0,0.5]^3, mid
        // 0.25) holds {0, 2}: 0 touches x = 0.25 and y = 0.25 with its corners, so children 0, 2,
        // 4 (z low), not 6 (x, y >= 0.25 needs x + y >= 0.5); 2 lies in the node's top face z =
        // 0.5: children 1, 3, 5 and 7 (its edge x + y = 0.5 touches (0.25, 0.25)). Nodes 9..16
        // are at maxDepth 2: leaves. Then node 2 = {2}, nodes 3..7 empty, node 8 = {1}.
        Octree t;
        t.root = Bounds3f(Vec3(0.0f), Vec3(1.0f));
        t.nodes = {interior(1, 3), interior(9, 2), leaf(7, 1), leaf(8, 0), leaf(8, 0), leaf(8, 0), leaf(8, 0),
                   leaf(8, 0),     leaf(8, 1),     leaf(0, 1), leaf(1, 1), leaf(2, 1), leaf(3, 1), leaf(4, 1),
                   leaf(5, 1),     leaf(6, 0),     leaf(6, 1)};
        t.primIndices = {0, 2, 0, 2, 0, 2, 2, 2, 1};
        cases.push_back({"the worked example (maxPrims 1, maxDepth 2)", workedExample(), options(1, 2), t});
    }
    {
        // The same with bounding boxes: triangle 0's box [0,0.25]^2 x [0,0] also touches child 6
        // of node 1, so node 15 holds {0} and every later list starts one further on.
        Octree t;
        t.root = Bounds3f(Vec3(0.0f), Vec3(1.0f));
        t.nodes = {interior(1, 3), interior(9, 2), leaf(8, 1), leaf(9, 0), leaf(9, 0), leaf(9, 0), leaf(9, 0),
                   leaf(9, 0),     leaf(9, 1),     leaf(0, 1), leaf(1, 1), leaf(2, 1), leaf(3, 1), leaf(4, 1),
                   leaf(5, 1),     leaf(6, 1),     leaf(7, 1)};
        t.primIndices = {0, 2, 0, 2, 0, 2, 0, 2, 2, 1};
        cases.push_back({"the worked example with insert=box", workedExample(), options(1, 2, OctreeInsertion::Box), t});
    }
    {
        Octree t;  // maxDepth 0: the root is a leaf whatever it holds
        t.root = Bounds3f(Vec3(0.0f), Vec3(1.0f));
        t.nodes = {leaf(0, 3)};
        t.primIndices = {0, 1, 2};
        cases.push_back({"the worked example with maxDepth 0", workedExample(), options(1, 0), t});
    }
    {
        // Two anchors in opposite corners make the root [0,1]^3; triangles 2 (z = 13/16) and 3
        // (z = 15/16) lie near (0.8125, 0.8125). Root: {0} to child 0, {1, 2, 3} to child 7.
        // Node 8 ([0.5,1]^3, mid 0.75): all three lie in its child 7: one child holds all, which
        // is no reason to stop: split. Node 16 ([0.75,1]^3, mid 0.875): 1 goes to child 7;
        // 2 (z low) touches x = 0.875 and y = 0.875 with its corners: children 0, 2, 4; 3 (z high):
        // 1, 3, 5. Nodes 17..24 are at maxDepth 3.
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {0.0625f, 0, 0}, {0, 0.0625f, 0});
        b.addTriangle({1, 1, 1}, {0.9375f, 1, 1}, {1, 0.9375f, 1});
        b.addTriangle({0.8125f, 0.8125f, 0.8125f}, {0.875f, 0.8125f, 0.8125f}, {0.8125f, 0.875f, 0.8125f});
        b.addTriangle({0.8125f, 0.8125f, 0.9375f}, {0.875f, 0.8125f, 0.9375f}, {0.8125f, 0.875f, 0.9375f});
        Octree t;
        t.root = Bounds3f(Vec3(0.0f), Vec3(1.0f));
        t.nodes = {interior(1, 4), leaf(0, 1), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0),
                   interior(9, 3), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0),
                   interior(17, 3), leaf(1, 1), leaf(2, 1), leaf(3, 1), leaf(4, 1), leaf(5, 1), leaf(6, 1), leaf(7, 0),
                   leaf(7, 1)};
        t.primIndices = {0, 2, 3, 2, 3, 2, 3, 1};
        cases.push_back({"a cluster in one child of a node is split anyway (maxPrims 2, maxDepth 3)", b.take(), options(2, 3), t});
    }
    {
        // Bounds [0,1] x [0,1] x [0,0], so the root is [0,1]^2 x [-0.5,0.5]: the triangles lie in
        // the mid-plane z = 0 and touch all eight children (the upper corner (0.5, 0.5) is on
        // the edge x + y = 1): every child would get all three, so the root stays a leaf.
        SceneBuilder b;
        for (int i = 0; i < 3; ++i) b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        Octree t;
        t.root = Bounds3f(Vec3(0, 0, -0.5f), Vec3(1, 1, 0.5f));
        t.nodes = {leaf(0, 3)};
        t.primIndices = {0, 1, 2};
        cases.push_back({"the memory rule: three copies of a triangle in the root's mid-plane (maxPrims 1)", b.take(), options(1, 10), t});
    }
    {
        Octree t;  // no primitives: the point box at the origin, one empty leaf
        t.root = Bounds3f(Vec3(0.0f));
        t.nodes = {leaf(0, 0)};
        cases.push_back({"an empty scene", SceneBuilder().take(), options(8, 10), t});
    }
    {
        // Triangle 0 has a NaN vertex: not placeable, in no node and not in the root's bounds,
        // which are those of 1 (near the origin) and 2 (near (1,1,1)): [0,1]^3. 1 goes to child
        // 0, 2 to child 7; the children are at maxDepth 1.
        const float nan = std::numeric_limits<float>::quiet_NaN();
        SceneBuilder b;
        b.addTriangle({nan, 0, 0}, {1, 0, 0}, {0, 1, 0});
        b.addTriangle({0, 0, 0}, {0.25f, 0, 0}, {0, 0.25f, 0});
        b.addTriangle({1, 1, 1}, {0.75f, 1, 1}, {1, 0.75f, 1});
        Octree t;
        t.root = Bounds3f(Vec3(0.0f), Vec3(1.0f));
        t.nodes = {interior(1, 2), leaf(0, 1), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 0), leaf(1, 1)};
        t.primIndices = {1, 2};
        cases.push_back({"a NaN vertex goes nowhere (maxPrims 1, maxDepth 1)", b.take(), options(1, 1), t});
    }
    return cases;
}

OctreeOptions stressOptions() { return options(1, 10); }

std::vector<OctreeStressScene> octreeStressScenes() {
    // Two small anchors in opposite corners make the root [0,1]^3 (ids 0 and 1).
    auto unitCube = [] {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {0.0625f, 0, 0}, {0, 0.0625f, 0});
        b.addTriangle({1, 1, 1}, {0.9375f, 1, 1}, {1, 0.9375f, 1});
        return b;
    };
    std::vector<OctreeStressScene> scenes;
    {
        // 2: OCT-01's X at z = 0.75 across x = 0.5; at y = 0.25 it spans x in [0.375, 0.625], at
        // y = 0.49 x in [0.495, 0.505]. 3: under (0.49, 0.49) at z = 0.5 (x + y <= 1 there).
        SceneBuilder b = unitCube();
        b.addTriangle({0.25f, 0, 0.75f}, {0.75f, 0, 0.75f}, {0.5f, 0.5f, 0.75f});
        b.addTriangle({0.4f, 0.4f, 0.5f}, {0.6f, 0.4f, 0.5f}, {0.4f, 0.6f, 0.5f});
        scenes.push_back({"OCT-01/02",
                          b.take(),
                          {
                              {"OCT-01 o (0.5, 0.25, -1) d (+0, 0, 1), in the mid-plane x = 0.5", makeRay({0.5f, 0.25f, -1}, {0, 0, 1}), 2, 1.75f},
                              {"OCT-01 d (-0, 0, 1)", makeRay({0.5f, 0.25f, -1}, {-0.0f, 0, 1}), 2, 1.75f},
                              {"OCT-01 d (-0, -0, 1)", makeRay({0.5f, 0.25f, -1}, {-0.0f, -0.0f, 1}), 2, 1.75f},
                              {"OCT-02 o (0.49, 0.49, -1) d (0, 0, 2)", makeRay({0.49f, 0.49f, -1}, {0, 0, 2}), 3, 0.75f},
                              {"OCT-02 o (0.49, 0.49, 2) d (0, 0, -2): past the X", makeRay({0.49f, 0.49f, 2}, {0, 0, -2}), 3, 0.75f},
                              {"OCT-02 o (0.49, 0.49, 2) d (-0, -0, -2)", makeRay({0.49f, 0.49f, 2}, {-0.0f, -0.0f, -2}), 3, 0.75f},
                              {"OCT-02 o (2, 0.49, 0.49) d (-1, 0, 0): in z = 0.49, nothing there", makeRay({2, 0.49f, 0.49f}, {-1, 0, 0}), kNoHit, 0},
                          }});
    }
    {
        // 2 at z = 0.1 and 3 at z = 0.9, both covering (x, y) with x + y <= 0.6 from (0.2, 0.2).
        SceneBuilder b = unitCube();
        b.addTriangle({0.2f, 0.2f, 0.1f}, {0.4f, 0.2f, 0.1f}, {0.2f, 0.4f, 0.1f});
        b.addTriangle({0.2f, 0.2f, 0.9f}, {0.4f, 0.2f, 0.9f}, {0.2f, 0.4f, 0.9f});
        scenes.push_back({"OCT-03",
                          b.take(),
                          {
                              {"OCT-03 o (0.25, 0.25, 0.3) inside, d (0, 0, 1)", makeRay({0.25f, 0.25f, 0.3f}, {0, 0, 1}), 3, 0.6f},
                              {"OCT-03 d (0, 0, -1)", makeRay({0.25f, 0.25f, 0.3f}, {0, 0, -1}), 2, 0.2f},
                              {"OCT-03 d (-0, -0, -1)", makeRay({0.25f, 0.25f, 0.3f}, {-0.0f, -0.0f, -1}), 2, 0.2f},
                              // At t = 0.6: (0.2875, 0.2875, 0.9), x + y = 0.575 <= 0.6.
                              {"OCT-03 d (0.0625, 0.0625, 1)", makeRay({0.25f, 0.25f, 0.3f}, {0.0625f, 0.0625f, 1}), 3, 0.6f},
                              {"OCT-03 tMin 0.7 passes the triangle ahead", makeRay({0.25f, 0.25f, 0.3f}, {0, 0, 1}, 0.7f), kNoHit, 0},
                          }});
    }
    {
        // One triangle per octant in the plane through (0.75, 0.75, 0.75) normal to the diagonal
        // (x + y + z = 2.25), mirrored into the others (coordinate c becomes 1 - c): its
        // centroid lies on that octant's diagonal through the centre, 0.25 from it in t.
        SceneBuilder b;
        for (int octant = 0; octant < 8; ++octant) {
            auto flip = [octant](Vec3 p) {
                for (int a = 0; a < 3; ++a)
                    if (!(octant & (4 >> a))) p[a] = 1.0f - p[a];
                return p;
            };
            b.addTriangle(flip({1, 0.625f, 0.625f}), flip({0.625f, 1, 0.625f}), flip({0.625f, 0.625f, 1}));
        }
        std::vector<OctreeStressRay> rays;
        for (int octant = 0; octant < 8; ++octant) {
            Vec3 d(octant & 4 ? 1.0f : -1.0f, octant & 2 ? 1.0f : -1.0f, octant & 1 ? 1.0f : -1.0f);
            rays.push_back({"OCT-04 from the centre along (" + std::to_string(int(d.x)) + ", " + std::to_string(int(d.y)) + ", " +
                                std::to_string(int(d.z)) + ")",
                            makeRay(Vec3(0.5f), d), uint32_t(octant), 0.25f});
        }
        scenes.push_back({"OCT-04", b.take(), rays});
    }
    {
        // 2 lies in y = 0.625 left of x = 0.5, its edge on x = 0.5 from z = 0.25 to 0.375; 3 is
        // its mirror image right of x = 0.5, in y = 0.75. A ray in the plane x = 0.5 meets their
        // edges; inclusive insertion puts each in the leaves on both sides of the plane.
        SceneBuilder b = unitCube();
        b.addTriangle({0.25f, 0.625f, 0.25f}, {0.5f, 0.625f, 0.25f}, {0.5f, 0.625f, 0.375f});
        b.addTriangle({0.75f, 0.75f, 0.25f}, {0.5f, 0.75f, 0.25f}, {0.5f, 0.75f, 0.375f});
        scenes.push_back({"OCT-05",
                          b.take(),
                          {
                              {"OCT-05 o (0.5, 0, 0.3125) d (+0, 1, 0)", makeRay({0.5f, 0, 0.3125f}, {0, 1, 0}), 2, 0.625f},
                              {"OCT-05 d (-0, 1, 0)", makeRay({0.5f, 0, 0.3125f}, {-0.0f, 1, 0}), 2, 0.625f},
                              {"OCT-05 o (0.5, 1, 0.3125) d (-0, -1, +0)", makeRay({0.5f, 1, 0.3125f}, {-0.0f, -1, 0}), 3, 0.25f},
                          }});
    }
    return scenes;
}

}  // namespace rtlab::grader
