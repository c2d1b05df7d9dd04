#include "grader/a5_kdtree/kd_cases.h"

#include "grader/kit/test_scenes.h"

#include <cmath>
#include <limits>

namespace rtlab::grader {
namespace {

using T = KdEventType;
using S = KdSide;

Bounds3f box(Vec3 lower, Vec3 upper) { return Bounds3f(lower, upper); }

// A box over [x0, x1] on x and the unit interval on y and z.
Bounds3f slabX(float x0, float x1) { return box({x0, 0, 0}, {x1, 1, 1}); }

Ray ray(Vec3 origin, Vec3 direction) {
    Ray r;
    r.origin = origin;
    r.direction = direction;
    return r;
}

const KdCosts kPbrt;  // K_T 1, K_I 80, eb 0.5

KdTreeOptions decisionOptions(uint32_t maxPrims = 1, KdCosts costs = kPbrt) {
    KdTreeOptions o;
    o.costs = costs;
    o.maxPrims = maxPrims;
    o.maxDepth = 20;
    return o;
}

KdSplit split(double cost) { return KdSplit{0, 0.5f, S::Below, cost, 1, 1}; }

}  // namespace

// Surface areas by hand, SA = 2 (dx dy + dy dz + dz dx); N1 = [0,4] x [0,2] x [0,1] has SA 28.
std::vector<SahCostCase> sahCostCases() {
    const Bounds3f n1 = box({0, 0, 0}, {4, 2, 1});
    const double inf = std::numeric_limits<double>::infinity();
    const float big = 0x1p64f;
    return {
        // below [0,1]: 10, above [1,4]: 22; 1 + 80 (10/28 3 + 22/28 5) = 1 + 80 * 140/28
        {"both sides hold primitives", n1, 0, 1.0f, 3, 5, kPbrt, 401.0},
        // 1 + 80 (1 - 0.5) (22/28 8)
        {"an empty side earns the bonus", n1, 0, 1.0f, 0, 8, kPbrt, 1.0 + 40.0 * 176.0 / 28.0},
        // below y in [0, 0.5]: 13, above: 23; 1 + 80 (13 2 + 23 2)/28
        {"a plane across y", n1, 1, 0.5f, 2, 2, kPbrt, 1.0 + 80.0 * 72.0 / 28.0},
        // K_T 2, K_I 5, eb 0.8: below z in [0, 0.25]: 19, above: 25; 2 + 5 (1 - 0.8) (25/28 4)
        {"other costs: K_T 2, K_I 5, eb 0.8, below empty", n1, 2, 0.25f, 0, 4, KdCosts{2, 5, 0.8}, 2.0 + 100.0 / 28.0},
        // eb 0: no bonus; 1 + 80 (22/28 8)
        {"eb 0: an empty side earns nothing", n1, 0, 1.0f, 0, 8, KdCosts{1, 80, 0}, 1.0 + 80.0 * 176.0 / 28.0},
        // flat in z: SA 2 (4 2) = 16, halves 4 and 12; 1 + 80 (4/16 + 12/16)
        {"a flat node (zero width on z)", box({0, 0, 1}, {4, 2, 1}), 0, 1.0f, 1, 1, kPbrt, 81.0},
        {"a segment: area 0, never split", box({0, 1, 1}, {4, 1, 1}), 0, 1.0f, 1, 1, kPbrt, inf},
        {"a point: area 0", box({2, 2, 2}, {2, 2, 2}), 0, 2.0f, 1, 0, kPbrt, inf},
        // side 2^64: SA 6 2^128 overflows float; halves 3 2^128 and 5 2^128; 1 + 80 (3/6 + 5/6)
        {"coordinates of 2^64: areas in double", box({0, 0, 0}, {big, big, big}), 0, 0x1p62f, 1, 1, kPbrt, 1.0 + 80.0 * 8.0 / 6.0},
        {"no primitives on either side", n1, 0, 2.0f, 0, 0, kPbrt, 1.0},
        // [-3,-1] x [-1,1]^2: SA 24; below dx 0.5: 12, above dx 1.5: 20; 1 + 80 (12/24 2 + 20/24)
        {"negative coordinates", box({-3, -1, -1}, {-1, 1, 1}), 0, -2.5f, 2, 1, kPbrt, 1.0 + 80.0 * 44.0 / 24.0},
    };
}

std::vector<EventOrderCase> eventOrderCases() {
    return {
        {"a smaller position first", {1, T::End, 5}, {2, T::Start, 0}, true},
        {"a larger position after", {2, T::Start, 0}, {1, T::End, 5}, false},
        {"End before Planar at one position", {1, T::End, 7}, {1, T::Planar, 2}, true},
        {"Planar before Start", {1, T::Planar, 2}, {1, T::Start, 0}, true},
        {"Start after End, whatever the indices", {1, T::Start, 0}, {1, T::End, 9}, false},
        {"Planar after End", {1, T::Planar, 0}, {1, T::End, 3}, false},
        {"same position and type: the lower index", {1, T::Start, 3}, {1, T::Start, 4}, true},
        {"an event is not before itself", {1, T::Start, 4}, {1, T::Start, 4}, false},
        {"-0.0 and +0.0 are one position", {-0.0f, T::End, 1}, {0.0f, T::Start, 0}, true},
        {"+0.0 Start after -0.0 End", {0.0f, T::Start, 0}, {-0.0f, T::End, 1}, false},
    };
}

std::vector<SortedEventsCase> sortedEventsCases() {
    // Box 0 spans [0,2] on x, box 1 [2,3], box 2 lies in the plane x = 2.
    std::vector<Bounds3f> three = {box({0, 0, 0}, {2, 1, 1}), box({2, 1, 0}, {3, 2, 0}), box({2, 0, 0}, {2, 3, 1})};
    std::vector<Bounds3f> walls(4, box({1, 0, 0}, {1, 1, 1}));
    return {
        {"x: an End, a Planar and a Start at 2", three, {2, 0, 1}, 0, {{0, T::Start, 0}, {2, T::End, 0}, {2, T::Planar, 2}, {2, T::Start, 1}, {3, T::End, 1}}},
        {"y: two Starts at 0 by index", three, {2, 0, 1}, 1, {{0, T::Start, 0}, {0, T::Start, 2}, {1, T::End, 0}, {1, T::Start, 1}, {2, T::End, 1}, {3, T::End, 2}}},
        {"z: box 1 is flat", three, {2, 0, 1}, 2, {{0, T::Planar, 1}, {0, T::Start, 0}, {0, T::Start, 2}, {1, T::End, 0}, {1, T::End, 2}}},
        {"identical flat boxes, two of four handed over", walls, {3, 1}, 0, {{1, T::Planar, 1}, {1, T::Planar, 3}}},
        {"one primitive of three", three, {1}, 0, {{2, T::Start, 1}, {3, T::End, 1}}},
        {"no primitives", three, {}, 0, {}},
    };
}

// Node areas: [0,4] x [0,1]^2 has SA 18 (a half of width w: 2 (2w + 1)); [0,2] x [0,1]^2 has 10;
// [0,3] x [0,1]^2 has 14; [0,2]^3 has 24.
std::vector<BestSplitCase> bestSplitCases() {
    const Bounds3f long4 = slabX(0, 4);
    return {
        {"equal costs: the lower position wins", long4, {slabX(0, 1), slabX(3, 4)}, kPbrt, KdSplit{0, 1, S::Below, 1.0 + 80.0 * 20.0 / 18.0, 1, 1},
         "x = 1 and x = 3 both give halves of 6 and 14 with one primitive each: 1 + 80 (6 + 14)/18; y and z have events only on the node's faces"},
        {"cutting off empty space", long4, {slabX(3, 3.5f), slabX(3.5f, 4)}, kPbrt, KdSplit{0, 3, S::Below, 1.0 + 40.0 * 12.0 / 18.0, 0, 2},
         "x = 3: below empty, 1 + 80 (1 - 0.5) (6/18 2) = 27.67; x = 3.5: 1 + 80 (16 + 4)/18 = 89.89"},
        {"a wall in the plane goes above", slabX(0, 2), {slabX(0, 0.5f), slabX(1.5f, 1.5f), slabX(1.75f, 2)}, kPbrt,
         KdSplit{0, 1.5f, S::Above, 1.0 + 80.0 * 16.0 / 10.0, 1, 2},
         "x = 0.5: 1 + 80 (4 1 + 8 2)/10 = 161; x = 1.5 planar below: 1 + 80 (8 2 + 4 1)/10 = 161, planar above: 1 + 80 (8 1 + 4 2)/10 = 129; "
         "x = 1.75 (the wall now below): 1 + 80 (9 2 + 3 1)/10 = 169"},
        {"equal costs on x and y: the lower axis wins", box({0, 0, 0}, {2, 2, 2}), {box({0, 0, 0}, {1, 1, 2}), box({1, 1, 0}, {2, 2, 2})}, kPbrt,
         KdSplit{0, 1, S::Below, 1.0 + 80.0 * 32.0 / 24.0, 1, 1}, "x = 1 and y = 1: halves of 16 with one primitive each; z has no candidate"},
        {"no plane strictly inside", slabX(0, 1), {slabX(0, 1), slabX(0, 1)}, kPbrt, KdSplit{}, "every event lies on the node's faces"},
        {"a box ending on the plane is below only", slabX(0, 3), {slabX(0, 1), slabX(1, 2), slabX(2, 3)}, kPbrt,
         KdSplit{0, 1, S::Below, 1.0 + 80.0 * 26.0 / 14.0, 1, 2},
         "x = 1: the box [0,1] below, [1,2] and [2,3] above: 1 + 80 (6 1 + 10 2)/14; x = 2 costs the same and comes later"},
        {"a flat node", box({0, 0, 0}, {2, 1, 0}), {box({0, 0, 0}, {1, 1, 0}), box({1, 0, 0}, {2, 1, 0})}, kPbrt, KdSplit{0, 1, S::Below, 81.0, 1, 1},
         "SA 4, halves 2 and 2: 1 + 80 (2/4 + 2/4); z has only planar events on the node's face"},
        {"boxes reaching out of the node", slabX(0, 2), {slabX(-1, 1), slabX(1, 3)}, kPbrt, KdSplit{0, 1, S::Below, 97.0, 1, 1},
         "events at -1 and 3 are no candidates but are counted: x = 1 gives 1 + 80 (6 + 6)/10"},
        {"a segment node: every candidate costs infinity", box({0, 1, 1}, {4, 1, 1}), {box({0, 1, 1}, {1, 1, 1}), box({3, 1, 1}, {4, 1, 1})}, kPbrt,
         KdSplit{}, "area 0: x = 1 and x = 3 cost +inf, never strictly below the initial +inf"},
    };
}

std::vector<ClassifyCase> classifyCases() {
    return {
        {"entirely below", slabX(0, 0.5f), 0, 1, S::Below, S::Below},
        {"entirely above", slabX(1.5f, 2), 0, 1, S::Below, S::Above},
        {"across the plane", slabX(0.5f, 1.5f), 0, 1, S::Below, S::Both},
        {"touching the plane from below", slabX(0.5f, 1), 0, 1, S::Above, S::Below},
        {"touching the plane from above", slabX(1, 1.5f), 0, 1, S::Below, S::Above},
        {"lying in the plane, planar side below", slabX(1, 1), 0, 1, S::Below, S::Below},
        {"lying in the plane, planar side above", slabX(1, 1), 0, 1, S::Above, S::Above},
        {"flat below the plane (the planar side does not matter)", slabX(0.5f, 0.5f), 0, 1, S::Above, S::Below},
        {"flat above the plane", slabX(2, 2), 0, 1, S::Below, S::Above},
        {"the axis is y", box({0, 2, 0}, {3, 4, 1}), 1, 2, S::Below, S::Above},
        {"-0.0 lies in the plane 0", box({-0.0f, 0, 0}, {-0.0f, 1, 1}), 0, 0, S::Above, S::Above},
        {"ending at -0.0 touches the plane 0 from below", box({-1, 0, 0}, {-0.0f, 1, 1}), 0, 0, S::Above, S::Below},
    };
}

// lround(8 + 1.3 k), k = floor(log2 N), at most 64.
std::vector<MaxDepthCase> maxDepthCases() {
    return {
        {"N = 0", 0, 8},
        {"N = 1", 1, 8},
        {"N = 2: 8 + 1.3 = 9.3", 2, 9},
        {"N = 3: k = 1", 3, 9},
        {"N = 4: 8 + 2.6 = 10.6", 4, 11},
        {"N = 31: k = 4, 13.2", 31, 13},
        {"N = 32: k = 5, 14.5 rounds away from zero", 32, 15},
        {"the bunny, N = 3674: k = 11, 22.3", 3674, 22},
        {"the engine, N = 121496: k = 16, 28.8", 121496, 29},
        {"N = 2^20 - 1: k = 19, 32.7", (1u << 20) - 1, 33},
        {"N = 2^20: k = 20, 34", 1u << 20, 34},
        {"N = 2^24 - 1: k = 23, 37.9 (float's log2 rounds up to 24)", (1u << 24) - 1, 38},
        {"N = 2^43: 63.9", uint64_t(1) << 43, 64},
        {"N = 2^44: 65.2, capped at 64", uint64_t(1) << 44, 64},
    };
}

// maxPrims 1, maxDepth 20, K_I 80: a leaf of n primitives costs 80 n.
std::vector<DecisionCase> decisionCases() {
    const KdTreeOptions o = decisionOptions();
    return {
        {"one primitive: a leaf", 1, 0, split(10), 0, o, {true, 0}},
        {"at the depth limit: a leaf", 5, 20, split(10), 0, o, {true, 0}},
        {"beyond the depth limit: a leaf", 5, 25, split(10), 1, o, {true, 1}},
        {"no plane: a leaf, bad refines unchanged", 5, 3, KdSplit{}, 1, o, {true, 1}},
        {"cheaper than the leaf: split", 5, 3, split(100), 0, o, {false, 0}},
        {"as dear as the leaf (400): split, no bad refine", 5, 3, split(400), 0, o, {false, 0}},
        {"dearer than the leaf: split, one bad refine", 5, 3, split(401), 0, o, {false, 1}},
        {"the third bad refine: a leaf", 5, 3, split(401), 2, o, {true, 3}},
        {"more than 4 leaf costs with n < 16: a leaf", 5, 3, split(1601), 0, o, {true, 1}},
        {"exactly 4 leaf costs: split", 5, 3, split(1600), 0, o, {false, 1}},
        {"more than 4 leaf costs with n = 16: split", 16, 3, split(5121), 0, o, {false, 1}},
        {"more than 4 leaf costs with n = 15: a leaf", 15, 3, split(4801), 0, o, {true, 1}},
        {"maxPrims 4, n = 4: a leaf", 4, 3, split(1), 0, decisionOptions(4), {true, 0}},
        {"maxPrims 4, n = 5: split", 5, 3, split(1), 0, decisionOptions(4), {false, 0}},
        {"one level above the depth limit: split", 2, 19, split(10), 2, o, {false, 2}},
        {"K_I 1: the leaf costs 5, a plane of 5.5 is a bad refine", 5, 3, split(5.5), 0, decisionOptions(1, KdCosts{1, 1, 0.5}), {false, 1}},
    };
}

// The plane x = 0.5 (z = 2 in one case); tSplit = (0.5 - o.x) / d.x, exact for these values.
std::vector<ChildOrderCase> childOrderCases() {
    const float inf = kInfinity, nan = std::numeric_limits<float>::quiet_NaN();
    const Vec3 o0(0, 0, 0), o1(1, 0, 0), onPlane(0.5f, 0, 0);
    return {
        {"from below, crossing within the segment: both", 0, 0.5f, ray(o0, {1, 0, 0}), 0, 10, {true, true, true, 0.5f}},
        {"from above, moving down: above first, both", 0, 0.5f, ray(o1, {-1, 0, 0}), 0, 10, {false, true, true, 0.5f}},
        {"crossing beyond tMax: the near child only", 0, 0.5f, ray(o0, {1, 0, 0}), 0, 0.25f, {true, true, false, 0.5f}},
        {"crossing before tMin: the far child only", 0, 0.5f, ray(o0, {1, 0, 0}), 0.75f, 2, {true, false, true, 0.5f}},
        {"moving away from the plane: tSplit < 0, the near child only", 0, 0.5f, ray(o1, {1, 0, 0}), 0, 10, {false, true, false, -0.5f}},
        {"KD-03: on the plane moving up: above only", 0, 0.5f, ray(onPlane, {1, 0, 0}), 0, 10, {false, true, false, 0.0f}},
        {"KD-03: on the plane moving down: below only", 0, 0.5f, ray(onPlane, {-1, 0, 0}), 0, 10, {true, true, false, -0.0f}},
        {"in the plane, d = +0: tSplit NaN, both, below first", 0, 0.5f, ray(onPlane, {0.0f, 1, 0}), 0, 10, {true, true, true, nan}},
        {"in the plane, d = -0: tSplit NaN, both, below first", 0, 0.5f, ray(onPlane, {-0.0f, 1, 0}), 0, 10, {true, true, true, nan}},
        {"parallel below, d = +0: tSplit +inf, below only", 0, 0.5f, ray(o0, {0.0f, 1, 0}), 0, 10, {true, true, false, inf}},
        {"parallel below, d = -0: tSplit -inf, below only", 0, 0.5f, ray(o0, {-0.0f, 1, 0}), 0, 10, {true, true, false, -inf}},
        {"parallel above, d = +0: tSplit -inf, above only", 0, 0.5f, ray(o1, {0.0f, 1, 0}), 0, 10, {false, true, false, -inf}},
        {"parallel above, d = -0: tSplit +inf, above only", 0, 0.5f, ray(o1, {-0.0f, 1, 0}), 0, 10, {false, true, false, inf}},
        {"crossing exactly at tMax: both", 0, 0.5f, ray(o0, {1, 0, 0}), 0, 0.5f, {true, true, true, 0.5f}},
        {"crossing exactly at tMin: both", 0, 0.5f, ray(o0, {1, 0, 0}), 0.5f, 2, {true, true, true, 0.5f}},
        {"the plane z = 2: tSplit = (2 + 2) / 0.5", 2, 2.0f, ray({0, 0, -2}, {0, 0, 0.5f}), 1, 10, {true, true, true, 8.0f}},
        {"an endless segment", 0, 0.5f, ray(o0, {0.25f, 0, 0}), 0, inf, {true, true, true, 2.0f}},
        {"crossing one ulp beyond tMax, within the margin: both", 0, 0.5f, ray(o0, {1, 0, 0}), 0, std::nextafter(0.5f, 0.0f),
         {true, true, true, 0.5f}},
        {"crossing one ulp before tMin, within the margin: both", 0, 0.5f, ray(o0, {1, 0, 0}), std::nextafter(0.5f, 1.0f), 2,
         {true, true, true, 0.5f}},
        {"crossing beyond the margin (tMax = 0.4999): the near child only", 0, 0.5f, ray(o0, {1, 0, 0}), 0, 0.4999f,
         {true, true, false, 0.5f}},
    };
}

// Trees built by hand, so the walk is judged on its own: each ray's hit, the primitives it tests
// in order (the order of the leaves and the mailbox), and the box test plus plane steps it
// counts. Every triangle lies in an axis plane or in x + z = 2.25, so every t is exact.
std::vector<WalkCase> walkCases() {
    auto wallX = [](SceneBuilder& b, float x, float y0, float y1, float z1) { b.addTriangle({x, y0, 0}, {x, y1, 0}, {x, y0, z1}); };
    std::vector<WalkCase> cases;
    {
        // KD-03: the plane x = 0.5 between L (prim 0, x = 0.25) and R (prim 1, x = 0.75); M (prim
        // 2) lies in z = 1 across the plane, so it is in both leaves.
        SceneBuilder b;
        wallX(b, 0.25f, 0, 2, 2);
        wallX(b, 0.75f, 0, 2, 2);
        b.addTriangle({0.3f, 0, 1}, {0.7f, 0, 1}, {0.5f, 2, 1});
        KdTree tree;
        tree.bounds = Bounds3f(Vec3(0.25f, 0, 0), Vec3(0.75f, 2, 2));
        tree.maxDepth = 1;
        tree.nodes = {KdNode::interior(0, 0.5f, 2), KdNode::leaf(0, 2), KdNode::leaf(2, 2)};
        tree.primIndices = {0, 2, 1, 2};
        const Vec3 onPlane(0.5f, 0.5f, 0.5f), inPlane(0.5f, 0.5f, 0);
        cases.push_back({"KD-03 (root x = 0.5, L below, R above, M in both)", b.take(), tree,
                         {{"on the plane moving down: L at 0.25, below only", ray(onPlane, {-1, 0, 0}), false, 0, 0.25f, {0, 2}, 2},
                          {"on the plane moving up: R at 0.25, above only", ray(onPlane, {1, 0, 0}), false, 1, 0.25f, {1, 2}, 2},
                          {"in the plane, d.x = +0: both leaves, M at 1 tested once", ray(inPlane, {0.0f, 0, 1}), false, 2, 1, {0, 2, 1}, 2},
                          {"in the plane, d.x = -0: the same", ray(inPlane, {-0.0f, 0, 1}), false, 2, 1, {0, 2, 1}, 2},
                          {"any hit, on the plane moving up", ray(onPlane, {1, 0, 0}), true, 1, 0, {}, 0}}});
    }
    {
        // B (prim 0) in the plane x + z = 2.25 reaches across x = 1; S (prim 1) lies in x = 1.25,
        // above; C (prim 2) in x = 0.5 covers y >= 1.5 only, below.
        SceneBuilder b;
        b.addTriangle({2.25f, -1, 0}, {2.25f, 3, 0}, {0.25f, 1, 2});
        wallX(b, 1.25f, 0, 2, 2);
        b.addTriangle({0.5f, 1.5f, 0}, {0.5f, 3, 0}, {0.5f, 1.5f, 2});
        KdTree tree;
        tree.bounds = Bounds3f(Vec3(0.25f, -1, 0), Vec3(2.25f, 3, 2));
        tree.maxDepth = 1;
        tree.nodes = {KdNode::interior(0, 1.0f, 2), KdNode::leaf(0, 2), KdNode::leaf(2, 2)};
        tree.primIndices = {0, 2, 0, 1};
        Ray shortRay = ray({0, 0.5f, 0.5f}, {1, 0, 0}), lateRay = shortRay;
        shortRay.tMax = 1.0f;
        lateRay.tMin = 1.5f;
        cases.push_back({"a hit beyond its leaf (root x = 1: B and C below, B and S above)", b.take(), tree,
                         {{"B at 1.75 from the below leaf, S at 1.25 above wins; B tested once", ray({0, 0.5f, 0.5f}, {1, 0, 0}), false, 1, 1.25f, {0, 2, 1}, 2},
                          {"from above: B at 1.25; the below leaf begins at 2, beyond it: not entered", ray({3, 2, 0.5f}, {-1, 0, 0}), false, 0, 1.25f, {0, 1}, 2},
                          {"tMax 1: nothing, both leaves entered (the plane is crossed at tMax)", shortRay, false, kNoHit, 0, {0, 2, 1}, 2},
                          {"tMin 1.5: the plane lies before the segment, above only; B at 1.75", lateRay, false, 0, 1.75f, {0, 1}, 2},
                          {"missing the tree's box: no plane step, no test", ray({0, 5, 0.5f}, {1, 0, 0}), false, kNoHit, 0, {}, 1},
                          {"any hit from below", ray({0, 0.5f, 0.5f}, {1, 0, 0}), true, 1, 0, {}, 0},
                          {"any hit within tMax 1: none", shortRay, true, 0, 0, {}, 0}}});
    }
    {
        // A chain 40 deep: level d cuts x = 40 - d, its above child a leaf with the wall at
        // x = 40.5 - d (prim 39 - d); the deepest below child, [0, 1], is empty. A ray along +x
        // leaves one pending node per level: 40 on the stack when it reaches the empty leaf, and
        // the nearest wall (prim 0 at x = 1.5) is in the last one pushed.
        SceneBuilder b;
        for (int k = 0; k < 40; ++k) wallX(b, 1.5f + float(k), 0, 2, 2);
        KdTree tree;
        tree.bounds = Bounds3f(Vec3(0, 0, 0), Vec3(41, 2, 2));
        tree.maxDepth = 40;
        for (uint32_t d = 0; d < 40; ++d) {
            // This level's interior node is at 2d, its below child at 2d + 1 (the next level or,
            // at the bottom, the empty leaf), its above leaf after the whole below subtree.
            tree.nodes.push_back(KdNode::interior(0, 40.0f - float(d), 80 - d));
        }
        tree.nodes.push_back(KdNode::leaf(0, 0));
        for (uint32_t d = 40; d-- > 0;) {
            tree.nodes.push_back(KdNode::leaf(uint32_t(tree.primIndices.size()), 1));
            tree.primIndices.push_back(39 - d);
        }
        cases.push_back({"KD-08 a tree 40 deep (the stack must hold one pending node per level)", b.take(), tree,
                         {{"along +x: 40 planes, 40 pending nodes, the nearest wall in the last one", ray({-1, 0.5f, 0.5f}, {1, 0, 0}), false, 0, 2.5f, {0}, 41},
                          {"any hit along +x", ray({-1, 0.5f, 0.5f}, {1, 0, 0}), true, 1, 0, {}, 0}}});
    }
    return cases;
}

}  // namespace rtlab::grader
