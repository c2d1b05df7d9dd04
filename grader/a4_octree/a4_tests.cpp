// Assignment a4: the octree. Truth tables for each pinned rule (the boxes, the triangle-box
// test, the pieces of Revelles' walk), the triangle-box test against the grader's own in double,
// hand-derived builds and the octree stress cases, the generic accelerator checks (structure,
// hit sets, efficiency, degenerate inputs) on the hit-set scenes and the teapot in a stadium, and
// the order of the leaves a walk enters against an exact oracle.
#include "framework/accel/octree/octree_accelerator.h"
#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "grader/a4_octree/a4_tests.h"
#include "grader/kit/image_tests.h"
#include "grader/a4_octree/given_octree.h"
#include "grader/a4_octree/octree_cases.h"
#include "grader/a4_octree/octree_oracle.h"
#include "grader/a4_octree/octree_structure.h"
#include "grader/a4_octree/octree_visit_order.h"
#include "grader/wire/scene_codec.h"
#include "grader/kit/stress_cases.h"
#include "grader/kit/failed_ray_cases.h"
#include "grader/kit/structure_tests.h"
#include "grader/kit/truth_table.h"
#include "grader/a4_octree/wire/octree_inputs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace rtlab::grader {
namespace {

constexpr const char* kA4 = "a4";
const std::string kStubRootBox = a4Stubs().name("octreeRootBox");
const std::string kStubChildBox = a4Stubs().name("childBox");
const std::string kStubChildIndex = a4Stubs().name("childIndex");
const std::string kStubBuild = a4Stubs().name("buildOctree");
const std::string kStubOverlap = a4Stubs().name("triangleOverlapsBox");
const std::string kStubMirror = a4Stubs().name("mirrorRay");
const std::string kStubRootSpan = a4Stubs().name("rootSpan");
const std::string kStubMid = a4Stubs().name("midParameters");
const std::string kStubFirst = a4Stubs().name("firstNode");
const std::string kStubNext = a4Stubs().name("nextNode");
const std::string kStubClosest = a4Stubs().name("intersectOctree");
const std::string kStubOccluded = a4Stubs().name("occludedOctree");

constexpr float kInf = kInfinity;
const float kNaN = std::numeric_limits<float>::quiet_NaN();

// Answers compared bit for bit where it matters: equal values, and the same sign of a zero.
bool same(float a, float b) { return a == b ? std::signbit(a) == std::signbit(b) : (std::isnan(a) && std::isnan(b)); }
bool same(const Vec3& a, const Vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
bool same(const Bounds3f& a, const Bounds3f& b) { return same(a.lower, b.lower) && same(a.upper, b.upper); }
bool same(int32_t a, int32_t b) { return a == b; }
bool same(const MirroredRay& a, const MirroredRay& b) {
    return same(a.ray.origin, b.ray.origin) && same(a.ray.direction, b.ray.direction) && a.ray.tMin == b.ray.tMin &&
           a.ray.tMax == b.ray.tMax && a.mask == b.mask;
}
bool same(const NodeSpan& a, const NodeSpan& b) { return same(a.t0, b.t0) && same(a.t1, b.t1); }

// Whether a phase of a multi-phase test completed; a stub still throwing NotImplemented leaves
// the whole test not started, anything else fails the cases of that phase with *reason.
enum class PhaseState { Complete, Failed, NotStarted };
PhaseState phaseState(const PhaseOutcome& outcome, TestResult& result, std::string* reason) {
    TestResult probe = makeResult(result.assignment, result.name);
    if (!failedPhaseResult(outcome, probe)) return PhaseState::Complete;
    if (probe.status == TestStatus::NotStarted) {
        result = probe;
        return PhaseState::NotStarted;
    }
    *reason = probe.reason;
    return PhaseState::Failed;
}

// Judges an answer read by `read` bit for bit against the case's (same), described by `describe`.
template <typename Read, typename Describe>
auto exactly(Read read, Describe describe) {
    return [read, describe](const auto& c, ByteReader& in) {
        auto got = read(in);
        return same(got, c.expected) ? std::string() : expectedGot(describe(c.expected), describe(got));
    };
}

template <typename T>
T readPlain(ByteReader& in) {
    return in.get<T>();
}

std::string childText(int32_t k) { return k == kOctreeEnd ? std::string("kOctreeEnd") : std::to_string(k); }

// --- The boxes ----------------------------------------------------------------------------------

using RootBoxCase = TableCase<Bounds3f, Bounds3f>;  // call: the primitives' bounds

std::vector<RootBoxCase> rootBoxCases() {
    auto box = [](Vec3 lo, Vec3 hi) { return Bounds3f(lo, hi); };
    return {
        // centre (2, 1, 0.5), side 4: half 2 on every axis.
        {"a 4 x 2 x 1 box: the cube of side 4 on its centre", box({0, 0, 0}, {4, 2, 1}), box({0, -1, -1.5f}, {4, 3, 2.5f})},
        {"a cube stays itself", box({-1, -1, -1}, {1, 1, 1}), box({-1, -1, -1}, {1, 1, 1})},
        {"negative coordinates", box({-3, -1, -1}, {-1, 1, 1}), box({-3, -1, -1}, {-1, 1, 1})},
        // centre (1, 1, 5), half 1.
        {"a flat box gets depth", box({0, 0, 5}, {2, 2, 5}), box({0, 0, 4}, {2, 2, 6})},
        {"a point: no extent", box({3, 3, 3}, {3, 3, 3}), box({3, 3, 3}, {3, 3, 3})},
        {"an empty box: the point at the origin", Bounds3f(), box({0, 0, 0}, {0, 0, 0})},
        // 1 + 16777218 = 16777219 is no float (the spacing is 2 there) and rounds to the even
        // 16777220: centre 8388610; the side 16777217 rounds to 16777216: half 8388608. The cube
        // starts at 2, one short of the bounds, and is extended to 1. y and z: centre 0.
        {"coordinates near 2^24: the rounded cube misses the bounds and is extended", box({1, 0, 0}, {16777218, 0, 0}),
         box({1, -8388608, -8388608}, {16777218, 8388608, 8388608})},
    };
}

using ChildBoxCase = TableCase<worker::ChildBoxCall, Bounds3f>;

std::vector<ChildBoxCase> childBoxCases() {
    // The root of the first root-box case: mid (2, 1, 0.5).
    const Bounds3f root(Vec3(0, -1, -1.5f), Vec3(4, 3, 2.5f));
    auto box = [](Vec3 lo, Vec3 hi) { return Bounds3f(lo, hi); };
    return {
        {"child 0: lower on every axis", {root, 0}, box({0, -1, -1.5f}, {2, 1, 0.5f})},
        {"child 1: z upper", {root, 1}, box({0, -1, 0.5f}, {2, 1, 2.5f})},
        {"child 2: y upper", {root, 2}, box({0, 1, -1.5f}, {2, 3, 0.5f})},
        {"child 4: x upper (bit 4 is x)", {root, 4}, box({2, -1, -1.5f}, {4, 1, 0.5f})},
        {"child 5: x and z upper", {root, 5}, box({2, -1, 0.5f}, {4, 1, 2.5f})},
        {"child 6: x and y upper", {root, 6}, box({2, 1, -1.5f}, {4, 3, 0.5f})},
        {"child 7: upper on every axis", {root, 7}, box({2, 1, 0.5f}, {4, 3, 2.5f})},
        {"a flat box keeps its plane", {box({0, 0, 5}, {2, 2, 5}), 3}, box({0, 1, 5}, {1, 2, 5})},
    };
}

using ChildIndexCase = TableCase<worker::ChildIndexCall, int32_t>;

std::vector<ChildIndexCase> childIndexCases() {
    const Vec3 half(0.5f), zero(0.0f);
    return {
        {"(0.75, 0.25, 0.75): x and z upper", {{0.75f, 0.25f, 0.75f}, half}, 5},
        {"(0.25, 0.75, 0.25): y upper", {{0.25f, 0.75f, 0.25f}, half}, 2},
        {"on all three mid-planes: upper", {half, half}, 7},
        {"one ulp below the x mid-plane", {{std::nextafter(0.5f, 0.0f), 0.5f, 0.25f}, half}, 2},
        {"NaN goes to the lower side", {{kNaN, 0.75f, 0.25f}, half}, 2},
        {"-0.0 >= +0.0: upper", {{-0.0f, -0.0f, -0.0f}, zero}, 7},
        {"+0.0 >= -0.0: upper", {zero, {-0.0f, -0.0f, -0.0f}}, 7},
        {"far away", {{1e30f, -1e30f, 0.5f}, half}, 5},
    };
}

std::vector<TestGroup> boxGroups() {
    return {tableGroup(kA4, "a4 root box", "a4/boxes/root-box", kStubRootBox, worker::kTaskOctreeRootBox, rootBoxCases(), exactly(readPlain<Bounds3f>, describeBox)),
            tableGroup(kA4, "a4 child box", "a4/boxes/child-box", kStubChildBox, worker::kTaskOctreeChildBox, childBoxCases(), exactly(readPlain<Bounds3f>, describeBox)),
            tableGroup(kA4, "a4 child index", "a4/boxes/child-index", kStubChildIndex, worker::kTaskOctreeChildIndex, childIndexCases(), exactly(readPlain<int32_t>, childText))};
}

// --- Triangle and box ---------------------------------------------------------------------------

using OverlapCase = TableCase<worker::TriangleBoxCall, bool>;

std::string overlapText(bool overlaps) { return overlaps ? "overlap" : "no overlap"; }
bool readOverlap(ByteReader& in) { return in.get<uint8_t>() != 0; }

std::vector<OverlapCase> overlapCases() {
    const Bounds3f unit(Vec3(0.0f), Vec3(1.0f));
    const Bounds3f flat(Vec3(0, 0, 0.5f), Vec3(1, 1, 0.5f));
    const Bounds3f far(Vec3(1024.0f), Vec3(1025.0f));
    return {
        {"inside", {{0.2f, 0.2f, 0.2f}, {0.8f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.2f}, unit}, true},
        {"far away (a box normal separates)", {{2, 2, 2}, {3, 2, 2}, {2, 3, 2}, unit}, false},
        // The slice z = 0.5 of the box ([0,1]^2) lies inside the triangle: x, y >= -5 and
        // x + y <= 5.
        {"a large triangle through the box, no vertex inside", {{-5, -5, 0.5f}, {10, -5, 0.5f}, {-5, 10, 0.5f}, unit}, true},
        {"a vertex on the box's corner (touching)", {{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, unit}, true},
        {"lying in the face x = 1", {{1, 0.2f, 0.2f}, {1, 0.8f, 0.2f}, {1, 0.2f, 0.8f}, unit}, true},
        {"parallel to the face x = 1, 1/16 away", {{1.0625f, 0.2f, 0.2f}, {1.0625f, 0.8f, 0.2f}, {1.0625f, 0.2f, 0.8f}, unit}, false},
        // The boxes overlap; the triangle lies in the plane x + y = 2.5 and the box has x + y <= 2:
        // the triangle's normal (1, 1, 0) separates.
        {"boxes overlap, the triangle's plane passes beyond the box", {{2.5f, 0, 0}, {0, 2.5f, 0}, {0, 2.5f, 1}, unit}, false},
        // The plane x + y + z = 3.5 passes beyond the corner (1, 1, 1) (sum 3). Every other axis
        // overlaps: the box normals ([0, 3.5] against [0, 1]) and the edge axes, which are box
        // normals or (1, 1, 0) and its like ([0, 3.5] against [0, 2]). Only the normal separates.
        {"only the triangle's normal separates", {{3.5f, 0, 0}, {0, 3.5f, 0}, {0, 0, 3.5f}, unit}, false},
        // e1 = p2 - p1 = (-0.5, 0.5, 0.75), axis e1 x y = (-0.75, 0, -0.5): the triangle projects
        // to [-2.125, -1.375], the box to [-1.25, 0]. The box normals only touch (x = 1), the
        // normal (0.375, 0.75, -0.25) gives 0.4375 inside the box's [-0.25, 1.125].
        {"only the edge axis e1 x y separates", {{1.5f, 0.5f, 2}, {1.5f, 0, 0.5f}, {1, 0.5f, 1.25f}, unit}, false},
        // Moved by -0.25 in z: the same axis gives [-2, -1.25] against [-1.25, 0]: touching, in
        // the vertex (1, 0.5, 1) on the box's edge.
        {"the same moved to touch the box's edge with a vertex", {{1.5f, 0.5f, 1.75f}, {1.5f, 0, 0.25f}, {1, 0.5f, 1}, unit}, true},
        // On the segment x + z = 2.25 (y = 0.5) beyond the box's x + z <= 2; the normal is zero.
        {"a segment (degenerate triangle) past the box's edge", {{2.25f, 0.5f, 0}, {0, 0.5f, 2.25f}, {0, 0.5f, 2.25f}, unit}, false},
        {"a segment through the box", {{-1, 0.5f, 0.5f}, {2, 0.5f, 0.5f}, {2, 0.5f, 0.5f}, unit}, true},
        {"a point inside", {{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, unit}, true},
        {"a point outside", {{1.5f, 0.5f, 0.5f}, {1.5f, 0.5f, 0.5f}, {1.5f, 0.5f, 0.5f}, unit}, false},
        {"a NaN vertex", {{kNaN, 0.5f, 0.5f}, {0.8f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.2f}, unit}, false},
        {"a flat box, a triangle crossing its plane", {{0.5f, 0.5f, 0}, {0.6f, 0.5f, 1}, {0.5f, 0.6f, 1}, flat}, true},
        {"a flat box, a triangle beside its plane", {{0.5f, 0.5f, 0.625f}, {0.6f, 0.5f, 1}, {0.5f, 0.6f, 1}, flat}, false},
        {"the inside case at 1024 (relative to the box's centre)",
         {{1024.2f, 1024.2f, 1024.2f}, {1024.8f, 1024.2f, 1024.2f}, {1024.2f, 1024.8f, 1024.2f}, far},
         true},
    };
}

// Random pairs: small triangles near the box's faces, long thin ones across it, segments.
std::vector<worker::TriangleBoxCall> overlapProperty(uint64_t seed, size_t count) {
    Pcg32 rng(seed, 23);
    auto in = [&](const Vec3& lo, const Vec3& hi) { return lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (hi - lo); };
    std::vector<worker::TriangleBoxCall> calls;
    for (size_t i = 0; i < count; ++i) {
        float scale = i % 4 == 3 ? 1000.0f : 1.0f;
        Bounds3f box(in(Vec3(-scale), Vec3(scale)), in(Vec3(-scale), Vec3(scale)));
        float size = (i % 3 == 0 ? 0.1f : i % 3 == 1 ? 2.0f : 0.5f) * scale;
        Vec3 c = in(box.lower - Vec3(0.3f * scale), box.upper + Vec3(0.3f * scale));
        Vec3 p0 = c + size * in(Vec3(-1.0f), Vec3(1.0f)), p1 = c + size * in(Vec3(-1.0f), Vec3(1.0f)), p2 = c + size * in(Vec3(-1.0f), Vec3(1.0f));
        if (i % 7 == 0) p2 = p1;
        calls.push_back({p0, p1, p2, box});
    }
    return calls;
}

TestGroup overlapGroup(uint64_t seed) {
    auto cases = std::make_shared<std::vector<OverlapCase>>(overlapCases());
    auto property = std::make_shared<std::vector<worker::TriangleBoxCall>>(overlapProperty(seed, 20000));
    ByteWriter propertyInput;
    propertyInput.putVector(*property);
    TestGroup group{kA4, "a4 triangle and box",
                    {tablePhase(kStubOverlap, worker::kTaskTriangleBox, *cases),
                     makePhase(kStubOverlap, worker::kTaskTriangleBox, std::move(propertyInput))},
                    {}};
    group.score = [cases, property](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult truth = makeResult(kA4, "a4/overlap/cases"), random = makeResult(kA4, "a4/overlap/property");
        scoreTable(run.phases[0], *cases, truth, [](const OverlapCase& c, ByteReader& in) {
            bool got = readOverlap(in);
            return got == c.expected ? std::string() : expectedGot(overlapText(c.expected), overlapText(got));
        });
        if (!failedPhaseResult(run.phases[1], random)) {
            ByteReader in(run.phases[1].data);
            size_t graded = 0, wrong = 0;
            std::string first;
            for (const worker::TriangleBoxCall& c : *property) {
                bool got = readOverlap(in);
                Overlap expected = triangleBoxOverlap({c.p0, c.p1, c.p2}, c.box, overlapSlack(c.box));
                if (expected == Overlap::Unsure) continue;
                ++graded;
                if (got == (expected == Overlap::Yes)) continue;
                std::string line = "triangle " + describeVec(c.p0) + ", " + describeVec(c.p1) + ", " + describeVec(c.p2) + " and box " +
                                   describeBox(c.box) + ": " + expectedGot(overlapText(expected == Overlap::Yes), overlapText(got));
                if (wrong++ < 5) random.details.push_back(line);
                if (first.empty()) first = line;
            }
            if (wrong == 0)
                markPassed(random, std::to_string(graded) + " random pairs agree with the separating-axis test in double (pairs within rounding of touching left out)");
            else markFailed(random, std::to_string(wrong) + " of " + std::to_string(graded) + " random pairs wrong; first: " + first);
        }
        results.push_back(std::move(truth));
        results.push_back(std::move(random));
    };
    return group;
}

// --- The pieces of the walk ---------------------------------------------------------------------

Ray ray(Vec3 o, Vec3 d, float tMin = 0.0f, float tMax = kInf) { return makeRay(o, d, tMin, tMax); }

using MirrorCase = TableCase<Ray, MirroredRay>;

std::string mirrorText(const MirroredRay& m) {
    return "o " + describeVec(m.ray.origin) + " d " + describeVec(m.ray.direction) + " (" + formatNumber(m.ray.tMin) + ", " +
           formatNumber(m.ray.tMax) + "] mask " + std::to_string(m.mask);
}

// The root of the root-box case: lower + upper = (4, 2, 1).
const Bounds3f kMirrorRoot(Vec3(0, -1, -1.5f), Vec3(4, 3, 2.5f));

std::vector<MirrorCase> mirrorCases() {
    return {
        {"no negative component: unchanged", ray({1, 0, 2}, {1, 2, 3}), {ray({1, 0, 2}, {1, 2, 3}), 0}},
        // x: 4 - 1 = 3; z: 1 - 2 = -1.
        {"x and z negative", ray({1, 0, 2}, {-1, 2, -3}), {ray({3, 0, -1}, {1, 2, 3}), 5}},
        // About the centre: (-1 + 3) - 0 = 2 (the root's size, 4, would give 4).
        {"y negative on the root [-1, 3]", ray({1, 0, 2}, {1, -2, 1}), {ray({1, 2, 2}, {1, 2, 1}), 2}},
        {"-0.0 is mirrored (signbit)", ray({2, 1, 0.5f}, {-0.0f, 0, -0.0f}), {ray({2, 1, 0.5f}, {0, 0, 0}), 5}},
        {"all three negative, tMin and tMax kept", ray({1, 0, 2}, {-1, -1, -1}, 0.5f, 7), {ray({3, 2, -1}, {1, 1, 1}, 0.5f, 7), 7}},
    };
}

using SpanCase = TableCase<Ray, NodeSpan>;

std::string spanText(const NodeSpan& s) { return "t0 " + describeVec(s.t0) + " t1 " + describeVec(s.t1); }

// On the root [0,1]^3; the rays are mirrored already (no negative component).
std::vector<SpanCase> spanCases() {
    return {
        // x: (0 + 1) / 1, (1 + 1) / 1; y, z parallel inside the slab.
        {"along x from outside; parallel inside y and z", ray({-1, 0.5f, 0.25f}, {1, 0, 0}), {{1, -kInf, -kInf}, {2, kInf, kInf}}},
        // (0 - 0.5) / 2 = -0.25, (1 - 0.5) / 2 = 0.25; /4: -0.125, 0.125; /0.5: -1, 1.
        {"from the centre", ray({0.5f, 0.5f, 0.5f}, {2, 4, 0.5f}), {{-0.25f, -0.125f, -1}, {0.25f, 0.125f, 1}}},
        {"parallel above the y slab: never in it", ray({0.5f, 2, 0.5f}, {1, 0, 1}), {{-0.5f, -kInf, -0.5f}, {0.5f, -kInf, 0.5f}}},
        {"parallel below the x slab: never in it", ray({-1, 0.5f, 0.5f}, {0, 1, 1}), {{kInf, -0.5f, -0.5f}, {kInf, 0.5f, 0.5f}}},
        {"parallel on the faces x = 0 and y = 1: inside", ray({0, 1, 0.5f}, {0, 0, 1}), {{-kInf, -kInf, -0.5f}, {kInf, kInf, 0.5f}}},
    };
}

using MidCase = TableCase<worker::MidCall, Vec3>;

std::vector<MidCase> midCases() {
    const Bounds3f unit(Vec3(0.0f), Vec3(1.0f)), away(Vec3(2.0f), Vec3(4.0f));
    return {
        {"no parallel axis: halfway", {ray({0, 0, 0}, {1, 1, 1}), {{1, 2, -1}, {3, 6, 1}}, unit}, {2, 4, 0}},
        // x: 0.25 < 0.5, the lower half: +inf; y: 0.75, the upper half: -inf.
        {"parallel to x (lower half) and y (upper half)", {ray({0.25f, 0.75f, -1}, {0, 0, 2}), {{-kInf, -kInf, 0.5f}, {kInf, kInf, 1}}, unit},
         {kInf, -kInf, 0.75f}},
        {"an origin on the mid-planes counts as the upper half", {ray({0.5f, 0.5f, -1}, {0, 0, 1}), {{-kInf, -kInf, 1}, {kInf, kInf, 2}}, unit},
         {-kInf, -kInf, 1.5f}},
        // The box's mid is 3: 2.9 lower, 3 upper.
        {"a box away from the origin", {ray({2.9f, 3, 0}, {0, 0, 1}), {{-kInf, -kInf, 2}, {kInf, kInf, 4}}, away}, {kInf, -kInf, 3}},
    };
}

using FirstNodeCase = TableCase<worker::FirstNodeCall, int32_t>;

std::vector<FirstNodeCase> firstNodeCases() {
    return {
        {"entry through x; tym < tx0", {{2, 1, 0}, {5, 1.5f, 3}}, 2},
        {"entry through y; txm < ty0", {{0, 2, 1}, {1, 5, 3}}, 4},
        {"entry through z; txm and tym < tz0", {{0, 1, 2}, {1, 1.5f, 5}}, 6},
        // The erratum: tzm < tx0 sets z, bit 1 (the table as printed set bit 4).
        {"entry through x; tzm < tx0 sets bit 1", {{2, 0, 0}, {5, 3, 1}}, 1},
        {"entry through y; tzm < ty0 sets bit 1", {{0, 2, 0}, {3, 5, 1}}, 1},
        {"tie x = y > z: entry through y", {{2, 2, 0}, {1, 5, 1}}, 5},
        {"tie x = z > y: entry through z", {{2, 0, 2}, {1, 1, 5}}, 6},
        {"tie y = z > x: entry through z", {{0, 2, 2}, {1, 5, 1}}, 4},
        {"all equal: entry through z", {{1, 1, 1}, {0, 0, 0}}, 6},
        {"tm equal to the entry parameter: not below it", {{2, 0, 0}, {5, 2, 2}}, 0},
        {"an origin inside (negative parameters)", {{-3, -1, -2}, {-2, 1, 0.5f}}, 4},
        {"parallel axes: -inf below everything, +inf above", {{-kInf, -kInf, 0.5f}, {-kInf, kInf, 2}}, 4},
    };
}

using NextNodeCase = TableCase<worker::NextNodeCall, int32_t>;

std::vector<NextNodeCase> nextNodeCases() {
    return {
        {"0 leaves through x", {0, {1, 2, 3}}, 4},
        {"4 leaves through x: the parent's face", {4, {1, 2, 3}}, kOctreeEnd},
        {"0 leaves through y", {0, {3, 1, 2}}, 2},
        {"2 leaves through y: the end", {2, {3, 1, 2}}, kOctreeEnd},
        {"0 leaves through z", {0, {3, 2, 1}}, 1},
        {"6 leaves through z", {6, {3, 2, 1}}, 7},
        {"tie x = y < z: through y", {0, {1, 1, 2}}, 2},
        {"tie x = z < y: through z", {0, {1, 2, 1}}, 1},
        {"tie y = z < x: through z", {0, {2, 1, 1}}, 1},
        {"all equal: through z", {0, {1, 1, 1}}, 1},
        {"tie x = z with z set: the end, not 5", {1, {1, 2, 1}}, kOctreeEnd},
        {"infinite exits of parallel axes", {0, {kInf, kInf, 5}}, 1},
        {"3 leaves through y: the end", {3, {2, 1, 3}}, kOctreeEnd},
    };
}

// The calls of mirrorRay and rootSpan share the root they are made on.
ByteWriter rootFirst(const Bounds3f& root) {
    ByteWriter input;
    input.put(root);
    return input;
}

std::vector<TestGroup> walkGroups() {
    return {tableGroup(kA4, "a4 mirroring", "a4/walk/mirror", kStubMirror, worker::kTaskOctreeMirror, mirrorCases(), exactly(readPlain<MirroredRay>, mirrorText), rootFirst(kMirrorRoot)),
            tableGroup(kA4, "a4 root span", "a4/walk/root-span", kStubRootSpan, worker::kTaskOctreeRootSpan, spanCases(), exactly(readPlain<NodeSpan>, spanText), rootFirst(Bounds3f(Vec3(0.0f), Vec3(1.0f)))),
            tableGroup(kA4, "a4 mid-plane parameters", "a4/walk/mid-parameters", kStubMid, worker::kTaskOctreeMid, midCases(), exactly(readPlain<Vec3>, describeVec)),
            tableGroup(kA4, "a4 first node", "a4/walk/first-node", kStubFirst, worker::kTaskOctreeFirstNode, firstNodeCases(), exactly(readPlain<int32_t>, childText)),
            tableGroup(kA4, "a4 next node", "a4/walk/next-node", kStubNext, worker::kTaskOctreeNextNode, nextNodeCases(), exactly(readPlain<int32_t>, childText))};
}

// --- Whole octrees ------------------------------------------------------------------------------

ChildPhase buildPhase(const Scene& scene, const OctreeOptions& options) {
    ByteWriter input;
    writeScene(scene, input);
    input.put(options);
    return makePhase(kStubBuild, worker::kTaskOctreeBuild, std::move(input));
}

// What a build phase sent back, or nullopt with *problem set.
std::optional<Octree> readOctree(const PhaseOutcome& outcome, std::string* problem) {
    try {
        ByteReader in(outcome.data);
        Octree octree;
        octree.root = in.get<Bounds3f>();
        octree.nodes = in.getVector<OctreeNode>(size_t(1) << 26);
        octree.primIndices = in.getVector<uint32_t>(size_t(1) << 28);
        return octree;
    } catch (const WireError& e) {
        *problem = std::string("the build sent malformed results: ") + e.what();
        return std::nullopt;
    }
}

std::string nodeText(const OctreeNode& n) {
    return "{firstChild " + std::to_string(n.firstChild) + ", primStart " + std::to_string(n.primStart) + ", primCount " +
           std::to_string(n.primCount) + "}";
}

// The first difference between a built octree and the hand-derived one, or "".
std::string treeDifference(const Octree& got, const Octree& expected) {
    if (!same(got.root, expected.root)) return "root " + describeBox(got.root) + " instead of " + describeBox(expected.root);
    for (size_t i = 0; i < std::min(got.nodes.size(), expected.nodes.size()); ++i) {
        const OctreeNode &g = got.nodes[i], &e = expected.nodes[i];
        if (g.firstChild != e.firstChild || g.primStart != e.primStart || g.primCount != e.primCount)
            return "node " + std::to_string(i) + " is " + nodeText(g) + ", expected " + nodeText(e);
    }
    if (got.nodes.size() != expected.nodes.size())
        return std::to_string(got.nodes.size()) + " nodes instead of " + std::to_string(expected.nodes.size());
    if (got.primIndices != expected.primIndices) {
        size_t k = 0;
        while (k < got.primIndices.size() && k < expected.primIndices.size() && got.primIndices[k] == expected.primIndices[k]) ++k;
        return "primIndices[" + std::to_string(k) + "] is " + (k < got.primIndices.size() ? std::to_string(got.primIndices[k]) : "missing") +
               ", expected " + (k < expected.primIndices.size() ? std::to_string(expected.primIndices[k]) : "none");
    }
    return "";
}

TestGroup buildCaseGroup() {
    auto cases = std::make_shared<std::vector<BuildCase>>(buildCases());
    TestGroup group{kA4, "a4 build cases", {}, {}};
    for (const BuildCase& c : *cases) group.phases.push_back(buildPhase(c.scene, c.options));
    group.score = [cases](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA4, "a4/octree/build-cases");
        CaseTally tally(result);
        for (size_t i = 0; i < cases->size(); ++i) {
            const BuildCase& c = (*cases)[i];
            std::string problem;
            PhaseState state = phaseState(run.phases[i], result, &problem);
            if (state == PhaseState::NotStarted) return results.push_back(std::move(result));
            if (state == PhaseState::Complete) {
                std::optional<Octree> got = readOctree(run.phases[i], &problem);
                if (got) problem = treeDifference(*got, c.expected);
            }
            tally.record(c.id, problem);
        }
        tally.finish();
        results.push_back(std::move(result));
    };
    return group;
}

std::string hitText(uint32_t prim, float t) { return prim == kNoHit ? std::string("a miss") : "prim " + std::to_string(prim) + " at t = " + formatNumber(t); }

// OCT-01 .. OCT-05: each scene built and traversed by the student's functions.
TestGroup stressGroup() {
    auto scenes = std::make_shared<std::vector<OctreeStressScene>>(octreeStressScenes());
    TestGroup group{kA4, "a4 octree stress cases", {}, {}};
    for (const OctreeStressScene& s : *scenes) {
        group.phases.push_back(buildPhase(s.scene, stressOptions()));
        std::vector<Ray> rays;
        for (const OctreeStressRay& r : s.rays) rays.push_back(r.ray);
        for (worker::QueryKind kind : {worker::QueryKind::Closest, worker::QueryKind::Occluded}) {
            ByteWriter input;
            input.put<uint8_t>(static_cast<uint8_t>(kind));
            input.putVector(rays);
            group.phases.push_back(makePhase(kind == worker::QueryKind::Closest ? kStubClosest : kStubOccluded, worker::kTaskOctreeQuery, std::move(input)));
        }
    }
    group.score = [scenes](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA4, "a4/walk/stress");
        CaseTally tally(result);
        for (size_t s = 0; s < scenes->size(); ++s) {
            const OctreeStressScene& scene = (*scenes)[s];
            // The build, then the closest-hit and any-hit answers of the scene's rays.
            std::string problem;
            std::optional<std::vector<worker::RawQuery>> hits, blocks;
            for (size_t k = 0; k < 3 && problem.empty(); ++k) {
                PhaseState state = phaseState(run.phases[3 * s + k], result, &problem);
                if (state == PhaseState::NotStarted) return results.push_back(std::move(result));
                if (state == PhaseState::Failed || k == 0) continue;
                TestResult read;
                (k == 1 ? hits : blocks) = readQueries(run.phases[3 * s + k], scene.rays.size(), read);
                if (!(k == 1 ? hits : blocks)) problem = read.reason;
            }
            for (size_t i = 0; i < scene.rays.size(); ++i) {
                const OctreeStressRay& r = scene.rays[i];
                std::string wrong = problem;
                if (wrong.empty()) {
                    const worker::RawQuery &hit = (*hits)[i], &block = (*blocks)[i];
                    bool hitRight = hit.prim == r.prim && (r.prim == kNoHit || std::abs(hit.t - r.t) <= 1e-6f * r.t);
                    if (!hitRight) wrong = "closest hit: " + expectedGot(hitText(r.prim, r.t), hitText(hit.prim, hit.t));
                    if ((block.prim != 0) != (r.prim != kNoHit))
                        wrong += std::string(wrong.empty() ? "" : "; ") + "any hit: " + (block.prim ? "occluded" : "not occluded");
                }
                tally.record(r.id + " " + describeRay(r.ray), wrong);
            }
        }
        tally.finish();
        results.push_back(std::move(result));
    };
    return group;
}

// The structure check needs the triangles (exact insertion), the plugin's check only sees the
// primitives' boxes: the build keeps every scene it sends, found again by its boxes.
class SceneMemo {
public:
    void keep(const Scene& scene) {
        std::lock_guard<std::mutex> lock(mutex_);
        scenes_.push_back(std::make_shared<const Scene>(scene));
    }
    std::shared_ptr<const Scene> find(const std::vector<Bounds3f>& primBounds) const {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& scene : scenes_) {
            if (scene->primitiveCount() != primBounds.size()) continue;
            bool match = true;
            for (uint32_t i = 0; i < primBounds.size() && match; ++i) match = same(scene->primitiveBounds(i), primBounds[i]);
            if (match) return scene;
        }
        return nullptr;
    }

private:
    mutable std::mutex mutex_;
    std::vector<std::shared_ptr<const Scene>> scenes_;
};

StructureReport checkOctree(const PhaseOutcome& build, const Scene& scene, const OctreeOptions& options) {
    StructureReport report;
    std::string problem;
    std::optional<Octree> octree = readOctree(build, &problem);
    if (!octree) {
        report.problems.push_back(problem);
        return report;
    }
    // The viewer's drawing hands each box down to the children a node names: only when every
    // interior node names eight that exist.
    bool childrenInRange = std::all_of(octree->nodes.begin(), octree->nodes.end(), [&](const OctreeNode& n) {
        return n.isLeaf() || size_t(n.firstChild) + kOctreeChildren <= octree->nodes.size();
    });
    if (childrenInRange) report.view = octreeStructureView(*octree, octreeNodeBoxes(*octree));
    OctreeStructureReport check = checkOctreeStructure(*octree, scene, options);
    report.problems = check.problems;
    report.problemCount = check.problemCount;
    report.summary = std::to_string(octree->nodes.size()) + " nodes, " + std::to_string(check.leaves) + " leaves, depth " +
                     std::to_string(check.depth) + ", " + std::to_string(octree->primIndices.size()) + " references (" +
                     formatNumber(double(octree->primIndices.size()) / double(std::max<uint32_t>(1, scene.primitiveCount()))) +
                     " per primitive)" + (check.unsure ? "; " + std::to_string(check.unsure) + " pairs within rounding of touching, either answer right" : "");
    return report;
}

// The octree as the generic structure tests see it, with the defaults (maxPrims 8, maxDepth 10,
// exact insertion).
StructurePlugin octreePlugin(std::shared_ptr<SceneMemo> memo) {
    const OctreeOptions options;
    StructurePlugin plugin;
    plugin.assignment = kA4;
    plugin.label = "octree";
    plugin.drawing = "octree";
    plugin.draw = drawLevels;
    plugin.traceAccelerator = "octree";
    plugin.build = [options, memo](const Scene& scene) {
        memo->keep(scene);
        return buildPhase(scene, options);
    };
    plugin.queryTask = worker::kTaskOctreeQuery;
    plugin.queries = {{"closest-hits", worker::QueryKind::Closest, kStubClosest}, {"any-hits", worker::QueryKind::Occluded, kStubOccluded}};
    plugin.given = givenOctree;
    plugin.givenQueryTask = worker::kTaskOctreeGivenQuery;
    plugin.check = [options, memo](const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope) {
        std::shared_ptr<const Scene> scene = memo->find(primBounds);
        if (!scene) throw Error("a4: the structure check met a scene the build never sent");
        return checkOctree(build, *scene, options);
    };
    return plugin;
}

// The order of the leaves the closest-hit walk enters, on the octree it built on this scene.
TestGroup visitOrderGroup(std::shared_ptr<PreparedScene> scene) {
    constexpr size_t kVisitRays = 300;
    auto rays = std::make_shared<std::vector<Ray>>(scene->rays.rays.begin(),
                                                   scene->rays.rays.begin() + std::min(kVisitRays, scene->rays.rays.size()));
    const OctreeOptions options;
    ByteWriter input;
    input.putVector(*rays);
    TestGroup group{kA4, "a4 leaf order on " + scene->test.id,
                    {buildPhase(scene->test.scene, options), makePhase(kStubClosest, worker::kTaskOctreeLeaves, std::move(input))},
                    {}};
    group.score = [scene, rays, options](const SandboxRun& run, std::vector<TestResult>& results) {
        const std::string tag = "[" + scene->test.id + "] ";
        TestResult result = makeResult(kA4, "a4/octree/visit-order");
        if (failedPhaseResult(run.phases[0], result) || failedPhaseResult(run.phases[1], result)) {
            results.push_back(std::move(result));
            return;
        }
        std::string problem;
        std::optional<Octree> octree = readOctree(run.phases[0], &problem);
        if (!octree || checkOctreeStructure(*octree, scene->test.scene, options).problemCount > 0) {
            markFailed(result, tag + "the octree is invalid (a4/octree/structure), so the order of its leaves means nothing");
            results.push_back(std::move(result));
            return;
        }
        std::vector<std::vector<uint32_t>> entered(rays->size());
        try {
            ByteReader in(run.phases[1].data);
            for (std::vector<uint32_t>& list : entered) {
                auto n = in.get<uint32_t>();
                if (n > worker::kMaxListedLeaves) throw WireError("a list of leaves longer than the limit");
                for (uint32_t i = 0; i < n; ++i) {
                    list.push_back(in.get<uint32_t>());
                    if (list.back() >= octree->nodes.size()) throw WireError("a leaf out of range");
                }
            }
        } catch (const WireError& e) {
            markFailed(result, tag + "sent malformed results: " + e.what());
            results.push_back(std::move(result));
            return;
        }
        VisitOrderVerdict verdict = judgeOctreeVisits(*octree, scene->test.scene, *rays, entered);
        for (const std::string& p : verdict.problems) result.details.push_back(tag + p);
        std::string line = tag + std::to_string(verdict.wrong) + " of " + std::to_string(verdict.graded) +
                           " rays enter leaves out of the exact order (rays within rounding of a leaf's edge or a triangle's are not graded; " +
                           std::to_string(allowedVisitOrderErrors(verdict.graded)) + " allowed)";
        if (verdict.wrong <= allowedVisitOrderErrors(verdict.graded)) {
            markPassed(result, line);
            results.push_back(std::move(result));
            return;
        }
        markFailed(result, line + "; first: " + verdict.problems.front());
        // The viewer steps through the leaves the walk entered against the exact order, in the octree it built.
        std::vector<Bounds3f> boxes = octreeNodeBoxes(*octree);
        for (size_t k = 0; k < verdict.wrongRays.size(); ++k) {
            size_t r = verdict.wrongRays[k];
            FailedCase failed;
            failed.title = tag + "a4/octree/visit-order: ray " + std::to_string(r);
            failed.notes = {verdict.problems[k]};
            failed.scene = sharedScene(scene);
            failed.accelerator = "octree";
            failed.draw = drawLevels;
            failed.structure = octreeStructureView(*octree, boxes);
            CaseRay& ray = failed.rays.emplace_back();
            ray.ray = (*rays)[r];
            ray.label = "ray " + std::to_string(r) + ": the leaves its walk entered, in order";
            ray.studentTrace = visitTrace(entered[r], TraceOpKind::LeafEntry);
            if (auto expected = expectedLeafOrder(*octree, boxes, scene->test.scene, (*rays)[r]))
                ray.expectedTrace = visitTrace(*expected, TraceOpKind::LeafEntry);
            addFailedCase(result, std::move(failed));
        }
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace

std::vector<TestGroup> a4Groups(GradingContext& context) {
    std::vector<TestGroup> groups = boxGroups();
    groups.push_back(overlapGroup(context.seed));
    for (TestGroup& g : walkGroups()) groups.push_back(std::move(g));
    groups.push_back(buildCaseGroup());
    groups.push_back(stressGroup());
    auto memo = std::make_shared<SceneMemo>();
    StructurePlugin octree = octreePlugin(memo);
    for (TestGroup& g : structureGroups(octree, context)) groups.push_back(std::move(g));
    // The stadium: graded for its hits, never for speed.
    groups.push_back(structureSceneGroup(octree, prepareScene(teapotInAStadium(context.modelsDir), context.seed), context));
    for (const auto& scene : hitSetScenes(context).list) groups.push_back(visitOrderGroup(scene));
    // Every scene rendered through the structure.
    for (TestGroup& g : imageGroups(context, {"a4", "octree", "the renderer with --accel octree (a0 + a4 functions)", kStubBuild}))
        groups.push_back(std::move(g));
    return groups;
}

}  // namespace rtlab::grader
