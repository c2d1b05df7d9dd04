#include "grader/a1_bvh/split_cases.h"


#include <algorithm>
#include <memory>

namespace rtlab::grader {
namespace {

Bounds3f box(Vec3 lo, Vec3 hi) { return Bounds3f(lo, hi); }

// An axis-aligned cube of side s with its lower corner at (x, y, z).
Bounds3f cube(float x, float y, float z, float s) { return box({x, y, z}, {x + s, y + s, z + s}); }

BvhOptions options(int maxLeaf, int buckets = 12, bool allAxes = false) {
    BvhOptions o;
    o.maxLeaf = maxLeaf;
    o.buckets = buckets;
    o.allAxes = allAxes;
    return o;
}

const char* functionStub(SplitFunction f) {
    switch (f) {
    case SplitFunction::Median: return "a1 splitMedian (assignments/a1_bvh/bvh_splits.cpp)";
    case SplitFunction::Middle: return "a1 splitMiddle (assignments/a1_bvh/bvh_splits.cpp)";
    case SplitFunction::EqualCounts: return "a1 splitEqualCounts (assignments/a1_bvh/bvh_splits.cpp)";
    case SplitFunction::SahSweep: return "a2 splitSahSweep (assignments/a2_sah/)";
    case SplitFunction::SahBuckets: return "a2 splitSahBuckets (assignments/a2_sah/)";
    }
    return "?";
}

std::string list(const std::vector<uint32_t>& v) {
    std::string s = "{";
    for (size_t i = 0; i < v.size(); ++i) {
        if (i) s += ',';
        s += std::to_string(v[i]);
    }
    return s + "}";
}

}  // namespace

std::vector<SplitCase> a1SplitCases() {
    // M1: node bounds are longest in y, centroid bounds longest in x.
    std::vector<Bounds3f> m1 = {box({0, -4, 0}, {0.25f, 4, 0.25f}), box({1, -0.125f, 0}, {1.25f, 0.125f, 0.25f}),
                                box({2, 0.875f, 0}, {2.25f, 1.125f, 0.25f}), box({3, -0.625f, 0}, {3.25f, -0.375f, 0.25f})};
    // M2: one far primitive pulls the midpoint to the right.
    std::vector<Bounds3f> m2;
    for (float x : {0.0f, 1.0f, 2.0f, 3.0f, 10.0f}) m2.push_back(cube(x, 0, 0, 0.25f));
    // M3: equal centroid coordinates, ordered by primitive index.
    std::vector<Bounds3f> m3;
    for (float c : {2.0f, 1.0f, 2.0f, 3.0f, 2.0f}) m3.push_back(box({c - 0.125f, 0, 0}, {c + 0.125f, 0.25f, 0.25f}));
    // M4: a centroid extent of one ulp; the midpoint rounds onto the lower centroid.
    const float up = 1.0f + 0x1p-23f;
    std::vector<Bounds3f> m4 = {box({0.75f, 0, 0}, {1.25f, 0.25f, 0.25f}), box({up - 0.25f, 0, 0}, {up + 0.25f, 0.25f, 0.25f}),
                                box({up - 0.25f, 0, 0}, {up + 0.25f, 0.25f, 0.25f})};
    const BvhOptions o = options(4);
    using F = SplitFunction;
    return {
        {"M1 median", F::Median, m1, o, 2, {3, 0}, "node bounds are longest in y (8 > 3.25); by (centroid y, index): 3 (-0.5), 0 (0), 1 (0), 2 (1); k = 4/2"},
        {"M1 equal counts", F::EqualCounts, m1, o, 2, {0, 1}, "centroid bounds are longest in x (3 > 1.5); by centroid x: 0, 1, 2, 3; k = 4/2"},
        {"M1 middle", F::Middle, m1, o, 2, {0, 1}, "centroid x in [0.125, 3.125], midpoint 1.625: left are 0 (0.125) and 1 (1.125)"},
        {"M2 middle", F::Middle, m2, o, 4, {0, 1, 2, 3}, "centroid x in [0.125, 10.125], midpoint 5.125: left are the four near the origin"},
        {"M2 equal counts", F::EqualCounts, m2, o, 2, {0, 1}, "k = 5/2 = 2 after ordering by centroid x"},
        {"M2 median", F::Median, m2, o, 2, {0, 1}, "longest node axis x; k = 5/2 = 2"},
        {"M3 equal counts (ties by index)", F::EqualCounts, m3, o, 2, {1, 0}, "centroids x 2,1,2,3,2; by (x, index): 1, 0, 2, 4, 3; k = 2"},
        {"M3 median (ties by index)", F::Median, m3, o, 2, {1, 0}, "as equal counts: longest node axis x; k = 2"},
        {"M3 middle", F::Middle, m3, o, 1, {1}, "midpoint (1 + 3)/2 = 2; only centroid 1 is < 2"},
        {"M4 middle (rounded midpoint, fallback)", F::Middle, m4, o, 1, {0},
         "centroids 1, 1+2^-23, 1+2^-23: the float midpoint rounds to 1, nothing is < 1, so equal counts: k = 3/2 = 1 (in exact arithmetic the answer is the same)"},
    };
}

std::vector<SplitCase> a2SplitCases() {
    std::vector<Bounds3f> s1 = {cube(0, 0, 0, 1), cube(1, 0, 0, 1), cube(10, 0, 0, 1), cube(11, 0, 0, 1)};
    std::vector<Bounds3f> s2 = {cube(0, 0, 0, 1), box({0.125f, 0, 0}, {1.125f, 1, 1})};
    std::vector<Bounds3f> s3 = {cube(0, 0, 0, 1), cube(2, 0, 0, 1), cube(4, 0, 0, 1)};
    std::vector<Bounds3f> s4 = {cube(0, 0, 0, 1), cube(0, 4, 0, 1), cube(4, 0, 0, 1), cube(4, 4, 0, 1)};
    std::vector<Bounds3f> s5 = {box({0, 0, 0}, {10, 1, 1}), box({6, 0, 0}, {16, 1, 1}), box({0, 3, 0}, {10, 4, 1}), box({6, 3, 0}, {16, 4, 1})};
    std::vector<Bounds3f> s6 = {box({-0.0625f, 0, 0}, {0.0625f, 0.125f, 0.125f}), box({0.4375f, 0, 0}, {0.5625f, 0.125f, 0.125f}),
                                box({0.9375f, 0, 0}, {1.0625f, 0.125f, 0.125f})};
    // S8: centroids x = 0, c8 and 0.9 (0.9f is the extent). 4 * c8 / 0.9 rounds to just below 3
    // in float, the reciprocal form c8 * (4 / 0.9) to exactly 3: only the pinned formula puts
    // c8 in bucket 2, on the left of the best plane. The third box is lifted to y = 0.6 (less
    // than the x extent, so x stays the longest centroid axis) to make that plane the best.
    const float c8 = 0x1.599998p-1f, h = 0.125f, q = 1.0f / 64;
    std::vector<Bounds3f> s8 = {box({-h, -h, -h}, {h, h, h}), box({c8 - h, -h, -h}, {c8 + h, h, h}),
                                box({0.9f - q, 0.6f - q, -q}, {0.9f + q, 0.6f + q, q})};
    std::vector<Bounds3f> s7;
    for (int i = 0; i < 5; ++i) s7.push_back(box({i / 64.0f, 0, 0}, {1 + i / 64.0f, 1, 1}));
    using F = SplitFunction;
    const char* s8Why = "centroid x 0, 0.675 (0x1.599998p-1), 0.9; B=4: bucket(0.675) = floor(4 * 0.675 / 0.9) = floor(2.9999998) = 2 in float "
                        "(the reciprocal form 0.675 * (4 / 0.9) gives 3.0: bucket 3); plane 2, {0,1}|{2}, weighs 2 * 1.05 + 0.0059 = 2.106, "
                        "plane 0 weighs 0.375 + 2 * 1.095 = 2.564; C = 1 + 2.106/2.432 = 1.87 < leaf 3. Partitioned with the binning's "
                        "bucket function, prims 0 and 1 go left";
    const char* s1Why = "S_N = 50; k=1: 1 + (6*1 + 46*3)/50 = 3.88; k=2: 1 + (10*2 + 10*2)/50 = 1.8; k=3: 3.88; 1.8 < leaf 4";
    const char* s2Why = "S_N = 6.5; the only split costs 1 + (6 + 6)/6.5 = 2.85";
    const char* s3Why = "S_N = 22; k=1 and k=2 both cost 1 + 34/22: the tie goes to the lower split index; 2.55 < leaf 3";
    const char* s4Why = "S_N = 70; x at k=2 and y at k=2 both cost 1 + 88/70: the lower axis (x) wins; 2.26 < leaf 4";
    const char* s5Why = "S_N = 168; longest centroid axis x: best k=2 costs 1 + 432/168 = 3.57 (< leaf 4); along y k=2 costs 1 + 264/168 = 2.57";
    const char* s6Why = "S_N = 0.59375; {0}|{1,2} and {0,1}|{2} both cost 1 + 0.78125/0.59375: the lower split wins; bucket(1) = B clamps to B-1";
    const char* s7Why = "S_N = 6.25; k=2 and k=3 cost 1 + 30.5/6.25 = 5.88, above the leaf's 5: split only because n = 5 > maxLeaf";
    return {
        {"S1 sweep", F::SahSweep, s1, options(4), 2, {0, 1}, s1Why},
        {"S1 buckets B=12", F::SahBuckets, s1, options(4, 12), 2, {0, 1}, std::string(s1Why) + "; buckets 0, 1, 10, 11"},
        {"S2 sweep, maxLeaf 4: leaf", F::SahSweep, s2, options(4), 0, {}, std::string(s2Why) + " >= leaf 2, and n = 2 <= maxLeaf: leaf"},
        {"S2 sweep, maxLeaf 1: split", F::SahSweep, s2, options(1), 1, {0}, std::string(s2Why) + ", but n = 2 > maxLeaf 1: split"},
        {"S2 buckets, maxLeaf 4: leaf", F::SahBuckets, s2, options(4, 12), 0, {}, std::string(s2Why) + " >= leaf 2: leaf"},
        {"S3 sweep (tie: lower split)", F::SahSweep, s3, options(4), 1, {0}, s3Why},
        {"S3 buckets B=12 (tie: lower plane)", F::SahBuckets, s3, options(4, 12), 1, {0}, std::string(s3Why) + "; buckets 0, 6, 11"},
        {"S4 sweep (tie of axes)", F::SahSweep, s4, options(4), 2, {0, 1}, s4Why},
        {"S4 sweep, all axes (tie: lower axis)", F::SahSweep, s4, options(4, 12, true), 2, {0, 1}, s4Why},
        {"S4 buckets, all axes (tie: lower axis)", F::SahBuckets, s4, options(4, 12, true), 2, {0, 1}, s4Why},
        {"S5 sweep, longest axis", F::SahSweep, s5, options(4), 2, {0, 2}, s5Why},
        {"S5 sweep, all axes", F::SahSweep, s5, options(4, 12, true), 2, {0, 1}, s5Why},
        {"S5 buckets B=12, longest axis", F::SahBuckets, s5, options(4, 12), 2, {0, 2}, s5Why},
        {"S5 buckets B=12, all axes", F::SahBuckets, s5, options(4, 12, true), 2, {0, 1}, s5Why},
        {"S6 sweep", F::SahSweep, s6, options(4), 1, {0}, s6Why},
        {"S6 buckets B=2 (clamp)", F::SahBuckets, s6, options(4, 2), 1, {0}, std::string(s6Why) + "; B=2: buckets 0, 1, 1"},
        {"S6 buckets B=4", F::SahBuckets, s6, options(4, 4), 1, {0}, std::string(s6Why) + "; B=4: buckets 0, 2, 3"},
        {"S7 sweep, maxLeaf 4: forced split", F::SahSweep, s7, options(4), 2, {0, 1}, s7Why},
        {"S7 sweep, maxLeaf 5: leaf", F::SahSweep, s7, options(5), 0, {}, std::string(s7Why) + "; with maxLeaf 5 the leaf (5) is cheaper"},
        {"S7 buckets B=4, maxLeaf 4", F::SahBuckets, s7, options(4, 4), 2, {0, 1}, std::string(s7Why) + "; buckets 0, 1, 2, 3, 3"},
        {"S7 buckets B=4, maxLeaf 5: leaf", F::SahBuckets, s7, options(5, 4), 0, {}, std::string(s7Why) + "; with maxLeaf 5 the leaf is cheaper"},
        {"S8 buckets B=4 (the bucket function of the binning partitions)", F::SahBuckets, s8, options(4, 4), 2, {0, 1}, s8Why},
    };
}

TestGroup splitCaseGroup(const std::string& assignment, const std::string& testName, std::vector<SplitCase> cases) {
    auto shared = std::make_shared<const std::vector<SplitCase>>(std::move(cases));
    TestGroup group;
    group.assignment = assignment;
    group.title = testName;
    ByteWriter input;
    input.put<uint64_t>(shared->size());
    for (const SplitCase& c : *shared) {
        input.put(worker::SplitCall{c.function, c.options});
        input.putVector(c.boxes);
    }
    group.phases = {noSetUp(), makePhase(functionStub(shared->front().function), worker::kTaskSplit, std::move(input))};
    group.score = [assignment, testName, shared](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(assignment, testName);
        if (!failedPhaseResult(run.phases[1], result)) {
            ByteReader in(run.phases[1].data);
            size_t passed = 0;
            std::string first;
            for (const SplitCase& c : *shared) {
                auto k = in.get<uint32_t>();
                std::vector<uint32_t> order(c.boxes.size());
                for (uint32_t& index : order) index = in.get<uint32_t>();
                std::vector<uint32_t> sorted = order;
                std::sort(sorted.begin(), sorted.end());
                bool permutation = true;
                for (uint32_t i = 0; i < sorted.size(); ++i) permutation &= sorted[i] == i;
                std::vector<uint32_t> left(order.begin(), order.begin() + std::min<size_t>(k, order.size()));
                std::sort(left.begin(), left.end());
                std::vector<uint32_t> expected = c.expectedLeft;
                std::sort(expected.begin(), expected.end());
                std::string problem;
                if (!permutation) problem = "the primitives after the call are not a reordering of the input: " + list(order);
                else if (k != c.expectedLeftCount) problem = "returned " + std::to_string(k) + ", expected " + std::to_string(c.expectedLeftCount);
                else if (k > 0 && left != expected) problem = "left part " + list(left) + ", expected " + list(expected);
                if (problem.empty()) {
                    ++passed;
                    continue;
                }
                std::string line = c.id + ": " + problem + " (" + c.derivation + ")";
                result.details.push_back(line);
                if (first.empty()) first = line;
            }
            setFromCounts(result, passed, shared->size(), first);
        }
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace rtlab::grader
