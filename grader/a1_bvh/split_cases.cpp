#include "grader/a1_bvh/split_cases.h"

#include <algorithm>
#include <memory>

namespace rtlab::grader {

BvhOptions splitOptions(int maxLeaf, int buckets, bool allAxes) {
    BvhOptions o;
    o.maxLeaf = maxLeaf;
    o.buckets = buckets;
    o.allAxes = allAxes;
    return o;
}

namespace {

// The function a case calls, as the stub tables name it.
const char* functionName(SplitFunction f) {
    switch (f) {
    case SplitFunction::Median: return "splitMedian";
    case SplitFunction::Middle: return "splitMiddle";
    case SplitFunction::EqualCounts: return "splitEqualCounts";
    case SplitFunction::SahSweep: return "splitSahSweep";
    case SplitFunction::SahBuckets: return "splitSahBuckets";
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
    std::vector<Bounds3f> m1 = {caseBox({0, -4, 0}, {0.25f, 4, 0.25f}), caseBox({1, -0.125f, 0}, {1.25f, 0.125f, 0.25f}),
                                caseBox({2, 0.875f, 0}, {2.25f, 1.125f, 0.25f}), caseBox({3, -0.625f, 0}, {3.25f, -0.375f, 0.25f})};
    // M2: one far primitive pulls the midpoint to the right.
    std::vector<Bounds3f> m2;
    for (float x : {0.0f, 1.0f, 2.0f, 3.0f, 10.0f}) m2.push_back(cube(x, 0, 0, 0.25f));
    // M3: equal centroid coordinates, ordered by primitive index.
    std::vector<Bounds3f> m3;
    for (float c : {2.0f, 1.0f, 2.0f, 3.0f, 2.0f}) m3.push_back(caseBox({c - 0.125f, 0, 0}, {c + 0.125f, 0.25f, 0.25f}));
    // M4: a centroid extent of one ulp; the midpoint rounds onto the lower centroid.
    const float up = 1.0f + 0x1p-23f;
    std::vector<Bounds3f> m4 = {caseBox({0.75f, 0, 0}, {1.25f, 0.25f, 0.25f}), caseBox({up - 0.25f, 0, 0}, {up + 0.25f, 0.25f, 0.25f}),
                                caseBox({up - 0.25f, 0, 0}, {up + 0.25f, 0.25f, 0.25f})};
    const BvhOptions o = splitOptions(4);
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

TestGroup splitCaseGroup(const StubTable& stubs, const std::string& testName, std::vector<SplitCase> cases) {
    const std::string assignment = stubs.assignment();
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
    group.phases = {noSetUp(), makePhase(stubs.name(functionName(shared->front().function)), worker::kTaskSplit, std::move(input))};
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
