// Assignment a2: the surface area heuristic, full sweep and buckets.
#include "grader/a2_sah/a2_tests.h"
#include "grader/a1_bvh/a1_tests.h"
#include "grader/a1_bvh/bvh_tests.h"
#include "grader/a1_bvh/split_cases.h"

namespace rtlab::grader {
namespace {

// Unit cases of the SAH splits with hand-derived answers (docs/grading.md, "Split functions").
std::vector<SplitCase> a2SplitCases() {
    std::vector<Bounds3f> s1 = {cube(0, 0, 0, 1), cube(1, 0, 0, 1), cube(10, 0, 0, 1), cube(11, 0, 0, 1)};
    std::vector<Bounds3f> s2 = {cube(0, 0, 0, 1), caseBox({0.125f, 0, 0}, {1.125f, 1, 1})};
    std::vector<Bounds3f> s3 = {cube(0, 0, 0, 1), cube(2, 0, 0, 1), cube(4, 0, 0, 1)};
    std::vector<Bounds3f> s4 = {cube(0, 0, 0, 1), cube(0, 4, 0, 1), cube(4, 0, 0, 1), cube(4, 4, 0, 1)};
    std::vector<Bounds3f> s5 = {caseBox({0, 0, 0}, {10, 1, 1}), caseBox({6, 0, 0}, {16, 1, 1}), caseBox({0, 3, 0}, {10, 4, 1}), caseBox({6, 3, 0}, {16, 4, 1})};
    std::vector<Bounds3f> s6 = {caseBox({-0.0625f, 0, 0}, {0.0625f, 0.125f, 0.125f}), caseBox({0.4375f, 0, 0}, {0.5625f, 0.125f, 0.125f}),
                                caseBox({0.9375f, 0, 0}, {1.0625f, 0.125f, 0.125f})};
    // S8: centroids x = 0, c8 and 0.9 (0.9f is the extent). 4 * c8 / 0.9 rounds to just below 3
    // in float, the reciprocal form c8 * (4 / 0.9) to exactly 3: only the pinned formula puts
    // c8 in bucket 2, on the left of the best plane. The third box is lifted to y = 0.6 (less
    // than the x extent, so x stays the longest centroid axis) to make that plane the best.
    const float c8 = 0x1.599998p-1f, h = 0.125f, q = 1.0f / 64;
    std::vector<Bounds3f> s8 = {caseBox({-h, -h, -h}, {h, h, h}), caseBox({c8 - h, -h, -h}, {c8 + h, h, h}),
                                caseBox({0.9f - q, 0.6f - q, -q}, {0.9f + q, 0.6f + q, q})};
    std::vector<Bounds3f> s7;
    for (int i = 0; i < 5; ++i) s7.push_back(caseBox({i / 64.0f, 0, 0}, {1 + i / 64.0f, 1, 1}));
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
        {"S1 sweep", F::SahSweep, s1, splitOptions(4), 2, {0, 1}, s1Why},
        {"S1 buckets B=12", F::SahBuckets, s1, splitOptions(4, 12), 2, {0, 1}, std::string(s1Why) + "; buckets 0, 1, 10, 11"},
        {"S2 sweep, maxLeaf 4: leaf", F::SahSweep, s2, splitOptions(4), 0, {}, std::string(s2Why) + " >= leaf 2, and n = 2 <= maxLeaf: leaf"},
        {"S2 sweep, maxLeaf 1: split", F::SahSweep, s2, splitOptions(1), 1, {0}, std::string(s2Why) + ", but n = 2 > maxLeaf 1: split"},
        {"S2 buckets, maxLeaf 4: leaf", F::SahBuckets, s2, splitOptions(4, 12), 0, {}, std::string(s2Why) + " >= leaf 2: leaf"},
        {"S3 sweep (tie: lower split)", F::SahSweep, s3, splitOptions(4), 1, {0}, s3Why},
        {"S3 buckets B=12 (tie: lower plane)", F::SahBuckets, s3, splitOptions(4, 12), 1, {0}, std::string(s3Why) + "; buckets 0, 6, 11"},
        {"S4 sweep (tie of axes)", F::SahSweep, s4, splitOptions(4), 2, {0, 1}, s4Why},
        {"S4 sweep, all axes (tie: lower axis)", F::SahSweep, s4, splitOptions(4, 12, true), 2, {0, 1}, s4Why},
        {"S4 buckets, all axes (tie: lower axis)", F::SahBuckets, s4, splitOptions(4, 12, true), 2, {0, 1}, s4Why},
        {"S5 sweep, longest axis", F::SahSweep, s5, splitOptions(4), 2, {0, 2}, s5Why},
        {"S5 sweep, all axes", F::SahSweep, s5, splitOptions(4, 12, true), 2, {0, 1}, s5Why},
        {"S5 buckets B=12, longest axis", F::SahBuckets, s5, splitOptions(4, 12), 2, {0, 2}, s5Why},
        {"S5 buckets B=12, all axes", F::SahBuckets, s5, splitOptions(4, 12, true), 2, {0, 1}, s5Why},
        {"S6 sweep", F::SahSweep, s6, splitOptions(4), 1, {0}, s6Why},
        {"S6 buckets B=2 (clamp)", F::SahBuckets, s6, splitOptions(4, 2), 1, {0}, std::string(s6Why) + "; B=2: buckets 0, 1, 1"},
        {"S6 buckets B=4", F::SahBuckets, s6, splitOptions(4, 4), 1, {0}, std::string(s6Why) + "; B=4: buckets 0, 2, 3"},
        {"S7 sweep, maxLeaf 4: forced split", F::SahSweep, s7, splitOptions(4), 2, {0, 1}, s7Why},
        {"S7 sweep, maxLeaf 5: leaf", F::SahSweep, s7, splitOptions(5), 0, {}, std::string(s7Why) + "; with maxLeaf 5 the leaf (5) is cheaper"},
        {"S7 buckets B=4, maxLeaf 4", F::SahBuckets, s7, splitOptions(4, 4), 2, {0, 1}, std::string(s7Why) + "; buckets 0, 1, 2, 3, 3"},
        {"S7 buckets B=4, maxLeaf 5: leaf", F::SahBuckets, s7, splitOptions(5, 4), 0, {}, std::string(s7Why) + "; with maxLeaf 5 the leaf is cheaper"},
        {"S8 buckets B=4 (the bucket function of the binning partitions)", F::SahBuckets, s8, splitOptions(4, 4), 2, {0, 1}, s8Why},
    };
}

}  // namespace

std::vector<TestGroup> a2Groups(GradingContext& context) {
    std::vector<TestGroup> groups;
    std::vector<SplitCase> sweep, buckets;
    for (const SplitCase& c : a2SplitCases()) (c.function == SplitFunction::SahSweep ? sweep : buckets).push_back(c);
    groups.push_back(splitCaseGroup(a2Stubs(), "a2/splits/sweep", sweep));
    groups.push_back(splitCaseGroup(a2Stubs(), "a2/splits/buckets", buckets));

    struct Variant {
        const char* label;
        SplitMethod method;
        int buckets;
        bool allAxes;
    };
    for (Variant v : {Variant{"sweep", SplitMethod::SahSweep, 12, false}, Variant{"sweep-all-axes", SplitMethod::SahSweep, 12, true},
                      Variant{"buckets-4", SplitMethod::SahBuckets, 4, false}, Variant{"buckets-12", SplitMethod::SahBuckets, 12, false},
                      Variant{"buckets-32", SplitMethod::SahBuckets, 32, false},
                      Variant{"buckets-12-all-axes", SplitMethod::SahBuckets, 12, true}}) {
        BvhConfig config;
        config.assignment = "a2";
        config.label = v.label;
        config.options.method = v.method;
        config.options.buckets = v.buckets;
        config.options.allAxes = v.allAxes;
        config.buildStub = a1Stubs().function("buildBvh") + " with " + a2Stubs().function(v.method == SplitMethod::SahSweep ? "splitSahSweep" : "splitSahBuckets");
        for (TestGroup& g : bvhConfigGroups(config, context)) groups.push_back(std::move(g));
    }
    return groups;
}

}  // namespace rtlab::grader
