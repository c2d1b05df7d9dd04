// The truth tables of a5's pure functions (docs/a5-kdtree.md, "How the grader checks it"): inputs
// and the answers derived by hand from the pinned rules, each with its derivation. Coordinates
// are dyadic where a value must be exact.
#pragma once

#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/kdtree.h"
#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct SahCostCase {
    std::string id;
    Bounds3f node;
    int axis;
    float position;
    uint32_t nBelow, nAbove;
    KdCosts costs;
    double expected;  // +inf for a node of area 0
};

struct EventOrderCase {
    std::string id;
    KdEvent a, b;
    bool before;  // kdEventBefore(a, b)
};

struct SortedEventsCase {
    std::string id;
    std::vector<Bounds3f> boxes;  // primitive i has box i
    std::vector<uint32_t> prims;  // the ids handed over, in this order
    int axis;
    std::vector<KdEvent> expected;
};

struct BestSplitCase {
    std::string id;
    Bounds3f node;
    std::vector<Bounds3f> boxes;  // primitive i has box i; every one is in the node
    KdCosts costs;
    KdSplit expected;             // axis -1: no candidate
    std::string derivation;
};

struct ClassifyCase {
    std::string id;
    Bounds3f box;
    int axis;
    float position;
    KdSide planarSide;
    KdSide expected;
};

struct MaxDepthCase {
    std::string id;
    uint64_t primCount;
    int expected;
};

struct DecisionCase {
    std::string id;
    uint32_t primCount;
    int depth;
    KdSplit best;
    int badRefines;
    KdTreeOptions options;  // maxDepth resolved
    KdNodeDecision expected;
};

struct ChildOrderCase {
    std::string id;
    int axis;
    float split;
    Ray ray;
    float tMin, tMax;
    KdChildOrder expected;  // tSplit compared by value; NaN must be NaN
};

// A ray through a tree the grader built by hand, and what the pinned traversal must do with it.
struct WalkRay {
    std::string id;
    Ray ray;
    bool occlusionQuery;           // any-hit instead of closest hit
    uint32_t prim;                 // closest hit: the primitive (kNoHit: a miss); any hit: 1 or 0
    float t;                       // closest hit: where
    std::vector<uint32_t> tested;  // closest hit: the primitives tested, in order
    uint32_t steps;                // closest hit: box tests + plane steps
};

struct WalkCase {
    std::string id;
    Scene scene;
    KdTree tree;
    std::vector<WalkRay> rays;
};

std::vector<SahCostCase> sahCostCases();
std::vector<EventOrderCase> eventOrderCases();
std::vector<SortedEventsCase> sortedEventsCases();
std::vector<BestSplitCase> bestSplitCases();
std::vector<ClassifyCase> classifyCases();
std::vector<MaxDepthCase> maxDepthCases();
std::vector<DecisionCase> decisionCases();
std::vector<ChildOrderCase> childOrderCases();
std::vector<WalkCase> walkCases();

}  // namespace rtlab::grader
