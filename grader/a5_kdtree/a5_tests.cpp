// Assignment a5: the KD-tree. Truth tables for each pinned rule (plane cost, event order, best
// plane, classification, depth limit and leaf rule, child order), the walk on trees built by
// hand, the whole tree checked node by node against the rules (grader/a5_kdtree/kd_oracle.h) with its SAH
// cost against the reference data, and the generic accelerator checks. Optional and worth no
// points: the O(N log N) build (the same tree) and the BSP autopartition (hit sets).
#include "grader/a5_kdtree/a5_tests.h"

#include "framework/accel/kdtree/kdtree_accelerator.h"
#include "grader/kit/image_tests.h"
#include "grader/a5_kdtree/given_kdtree.h"
#include "grader/kit/hit_judge.h"
#include "grader/a5_kdtree/kd_cases.h"
#include "grader/a5_kdtree/kd_oracle.h"
#include "grader/wire/scene_codec.h"
#include "grader/a5_kdtree/wire/kdtree_codec.h"
#include "grader/kit/structure_tests.h"
#include "grader/kit/truth_table.h"
#include "grader/a5_kdtree/wire/kdtree_inputs.h"

#include <cmath>
#include <cstdio>

namespace rtlab::grader {
namespace {

constexpr const char* kA5 = "a5";
const std::string kStubSah = a5Stubs().name("kdSahCost");
const std::string kStubEventOrder = a5Stubs().name("kdEventBefore");
const std::string kStubSortedEvents = a5Stubs().name("kdSortedEvents");
const std::string kStubBestSplit = a5Stubs().name("kdBestSplit");
const std::string kStubClassify = a5Stubs().name("kdClassify");
const std::string kStubMaxDepth = a5Stubs().name("kdMaxDepth");
const std::string kStubDecide = a5Stubs().name("kdDecideNode");
const std::string kStubChildOrder = a5Stubs().name("kdChildOrder");
const std::string kStubClosest = a5Stubs().name("intersectKdTree");
const std::string kStubOccluded = a5Stubs().name("occludedKdTree");
const std::string kEntryBuild = a5Stubs().name("buildKdTree");
const std::string kStubBuild = kEntryBuild + " with the a5 functions it calls";
const std::string kStubBuildNlogN = a5Stubs().name("buildKdTreeNlogN");
const std::string kStubBsp = a5Stubs().name("buildBspAutopartition");
const std::string kStubBspClosest = a5Stubs().name("intersectBsp");
const std::string kStubBspOccluded = a5Stubs().name("occludedBsp");

const char* const kAxes[] = {"x", "y", "z"};
const char* const kSides[] = {"below", "above", "both"};
const char* const kEventTypes[] = {"End", "Planar", "Start"};

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::string sideName(KdSide side) { return uint8_t(side) < 3 ? kSides[uint8_t(side)] : "an invalid side"; }

std::string describeEvent(const KdEvent& e) {
    return "(" + formatNumber(e.position) + ", " + (uint8_t(e.type) < 3 ? kEventTypes[uint8_t(e.type)] : "?") + ", " + std::to_string(e.prim) + ")";
}

std::string describeSplit(const KdSplit& s) {
    if (!s.found()) return "no plane";
    return std::string(s.axis >= 0 && s.axis < 3 ? kAxes[s.axis] : "?") + " = " + formatNumber(s.position) + ", planar " + sideName(s.planarSide) +
           ", cost " + number(s.cost) + ", " + std::to_string(s.nBelow) + " below, " + std::to_string(s.nAbove) + " above";
}

// --- The cost of a plane, events ----------------------------------------------------------------

TestGroup sahGroup() {
    auto cases = std::make_shared<std::vector<SahCostCase>>(sahCostCases());
    TestGroup group{kA5, "a5 plane cost",
                    {tablePhase(kStubSah, worker::kTaskKdSahCost, *cases, [](const SahCostCase& c) {
                        return worker::KdSahCall{c.node, c.axis, c.position, c.nBelow, c.nAbove, c.costs};
                    })},
                    {}};
    group.score = [cases](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA5, "a5/sah/plane-cost");
        scoreTable(run.phases[0], *cases, result, [](const SahCostCase& c, ByteReader& in) -> std::string {
            double got = in.get<double>();
            bool right = std::isinf(c.expected) ? got == c.expected : std::abs(got - c.expected) <= 1e-12 * std::abs(c.expected);
            return right ? "" : "expected " + number(c.expected) + ", got " + number(got);
        });
        results.push_back(std::move(result));
    };
    return group;
}

TestGroup eventsGroup() {
    auto order = std::make_shared<std::vector<EventOrderCase>>(eventOrderCases());
    auto sorted = std::make_shared<std::vector<SortedEventsCase>>(sortedEventsCases());
    ByteWriter sortedInput;
    sortedInput.put<uint64_t>(sorted->size());
    for (const SortedEventsCase& c : *sorted) {
        sortedInput.putVector(c.boxes);
        sortedInput.putVector(c.prims);
        sortedInput.put<int32_t>(c.axis);
    }
    TestGroup group{kA5, "a5 events",
                    {tablePhase(kStubEventOrder, worker::kTaskKdEventOrder, *order,
                                                     [](const EventOrderCase& c) { return worker::KdEventPair{c.a, c.b}; }),
                     makePhase(kStubSortedEvents, worker::kTaskKdSortedEvents, std::move(sortedInput))},
                    {}};
    group.score = [order, sorted](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult before = makeResult(kA5, "a5/events/order"), list = makeResult(kA5, "a5/events/sorted");
        scoreTable(run.phases[0], *order, before, [](const EventOrderCase& c, ByteReader& in) -> std::string {
            bool got = in.get<uint8_t>() != 0;
            return got == c.before ? ""
                                   : "kdEventBefore(" + describeEvent(c.a) + ", " + describeEvent(c.b) + ") returned " + (got ? "true" : "false");
        });
        scoreTable(run.phases[1], *sorted, list, [](const SortedEventsCase& c, ByteReader& in) -> std::string {
            auto got = in.getVector<KdEvent>(2 * c.prims.size() + 1);
            if (got == c.expected) return "";
            auto joined = [](const std::vector<KdEvent>& events) {
                std::string text;
                for (const KdEvent& e : events) text.append(" ").append(describeEvent(e));
                return text;
            };
            return "expected" + joined(c.expected) + "; got" + joined(got);
        });
        results.push_back(std::move(before));
        results.push_back(std::move(list));
    };
    return group;
}

// --- The best plane, classification -------------------------------------------------------------

// A node's events as the grader sorts them itself: the student's kdBestSplit gets correct input.
std::array<std::vector<KdEvent>, 3> sortedEventsOf(const std::vector<Bounds3f>& boxes) {
    std::array<std::vector<KdEvent>, 3> events;
    for (int axis = 0; axis < 3; ++axis) {
        for (uint32_t prim = 0; prim < boxes.size(); ++prim) {
            float lo = boxes[prim].lower[axis], hi = boxes[prim].upper[axis];
            if (lo == hi) events[axis].push_back({lo, KdEventType::Planar, prim});
            else {
                events[axis].push_back({lo, KdEventType::Start, prim});
                events[axis].push_back({hi, KdEventType::End, prim});
            }
        }
        std::sort(events[axis].begin(), events[axis].end(), [](const KdEvent& a, const KdEvent& b) {
            return a.position != b.position ? a.position < b.position : a.type != b.type ? a.type < b.type : a.prim < b.prim;
        });
    }
    return events;
}

TestGroup splitGroup() {
    auto best = std::make_shared<std::vector<BestSplitCase>>(bestSplitCases());
    auto classify = std::make_shared<std::vector<ClassifyCase>>(classifyCases());
    ByteWriter bestInput;
    bestInput.put<uint64_t>(best->size());
    for (const BestSplitCase& c : *best) {
        bestInput.put(worker::KdSplitCall{c.node, uint32_t(c.boxes.size()), c.costs});
        for (const std::vector<KdEvent>& list : sortedEventsOf(c.boxes)) bestInput.putVector(list);
    }
    TestGroup group{kA5, "a5 best plane and classification",
                    {makePhase(kStubBestSplit, worker::kTaskKdBestSplit, std::move(bestInput)),
                     tablePhase(kStubClassify, worker::kTaskKdClassify, *classify,
                                                        [](const ClassifyCase& c) {
                                                            return worker::KdClassifyCall{c.box, c.axis, c.position, c.planarSide};
                                                        })},
                    {}};
    group.score = [best, classify](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult plane = makeResult(kA5, "a5/split/best-plane"), side = makeResult(kA5, "a5/split/classify");
        scoreTable(run.phases[0], *best, plane, [](const BestSplitCase& c, ByteReader& in) -> std::string {
            auto got = in.get<KdSplit>();
            const KdSplit& e = c.expected;
            bool right = got.found() == e.found() &&
                         (!e.found() || (got.axis == e.axis && got.position == e.position && got.planarSide == e.planarSide &&
                                         got.nBelow == e.nBelow && got.nAbove == e.nAbove && std::abs(got.cost - e.cost) <= 1e-12 * e.cost));
            return right ? "" : "expected " + describeSplit(e) + ", got " + describeSplit(got) + " (" + c.derivation + ")";
        });
        scoreTable(run.phases[1], *classify, side, [](const ClassifyCase& c, ByteReader& in) -> std::string {
            auto got = KdSide(in.get<uint8_t>());
            return got == c.expected ? "" : "expected " + sideName(c.expected) + ", got " + sideName(got);
        });
        results.push_back(std::move(plane));
        results.push_back(std::move(side));
    };
    return group;
}

// --- When to stop --------------------------------------------------------------------------------

TestGroup leafGroup() {
    auto depths = std::make_shared<std::vector<MaxDepthCase>>(maxDepthCases());
    auto decisions = std::make_shared<std::vector<DecisionCase>>(decisionCases());
    TestGroup group{kA5, "a5 depth limit and leaf rule",
                    {tablePhase(kStubMaxDepth, worker::kTaskKdMaxDepth, *depths, [](const MaxDepthCase& c) { return c.primCount; }),
                     tablePhase(kStubDecide, worker::kTaskKdDecide, *decisions,
                                                      [](const DecisionCase& c) {
                                                          return worker::KdDecideCall{c.primCount, c.depth, c.best, c.badRefines, c.options};
                                                      })},
                    {}};
    group.score = [depths, decisions](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult depth = makeResult(kA5, "a5/leaf/max-depth"), rule = makeResult(kA5, "a5/leaf/rule");
        scoreTable(run.phases[0], *depths, depth, [](const MaxDepthCase& c, ByteReader& in) -> std::string {
            auto got = in.get<int32_t>();
            return got == c.expected ? "" : "expected " + std::to_string(c.expected) + ", got " + std::to_string(got);
        });
        scoreTable(run.phases[1], *decisions, rule, [](const DecisionCase& c, ByteReader& in) -> std::string {
            auto got = in.get<KdNodeDecision>();
            auto text = [](const KdNodeDecision& d) { return std::string(d.leaf ? "a leaf" : "a split") + " with " + std::to_string(d.badRefines) + " bad refines"; };
            return got.leaf == c.expected.leaf && got.badRefines == c.expected.badRefines ? "" : "expected " + text(c.expected) + ", got " + text(got);
        });
        results.push_back(std::move(depth));
        results.push_back(std::move(rule));
    };
    return group;
}

// --- Traversal ----------------------------------------------------------------------------------

TestGroup childOrderGroup() {
    auto cases = std::make_shared<std::vector<ChildOrderCase>>(childOrderCases());
    TestGroup group{kA5, "a5 child order",
                    {tablePhase(kStubChildOrder, worker::kTaskKdChildOrder, *cases,
                                                          [](const ChildOrderCase& c) {
                                                              return worker::KdChildOrderCall{c.axis, c.split, c.ray, c.tMin, c.tMax};
                                                          })},
                    {}};
    group.score = [cases](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA5, "a5/traversal/child-order");
        scoreTable(run.phases[0], *cases, result, [](const ChildOrderCase& c, ByteReader& in) -> std::string {
            auto got = in.get<KdChildOrder>();
            auto text = [](const KdChildOrder& o) {
                std::string visits = o.visitFirst && o.visitSecond ? "both" : o.visitFirst ? "the first only" : o.visitSecond ? "the second only" : "neither";
                return std::string(o.belowFirst ? "below" : "above") + " first, " + visits + ", tSplit " + formatNumber(o.tSplit);
            };
            const KdChildOrder& e = c.expected;
            bool sameT = std::isnan(e.tSplit) ? std::isnan(got.tSplit) : got.tSplit == e.tSplit;
            bool right = got.belowFirst == e.belowFirst && got.visitFirst == e.visitFirst && got.visitSecond == e.visitSecond && sameT;
            return right ? "" : "segment [" + formatNumber(c.tMin) + ", " + formatNumber(c.tMax) + "] of " + describeRay(c.ray) + ": expected " + text(e) +
                                    ", got " + text(got);
        });
        results.push_back(std::move(result));
    };
    return group;
}

std::string listText(const std::vector<uint32_t>& prims) {
    std::string text = "[";
    for (size_t i = 0; i < prims.size(); ++i) text += (i ? ", " : "") + std::to_string(prims[i]);
    return text + "]";
}

ChildPhase walkPhase(const WalkCase& c, worker::QueryKind kind, const std::vector<Ray>& rays) {
    ByteWriter input;
    writeScene(c.scene, input);
    writeKdTree(input, c.tree);
    input.put<uint8_t>(static_cast<uint8_t>(kind));
    input.putVector(rays);
    return makePhase(kind == worker::QueryKind::Occluded ? kStubOccluded : kStubClosest, worker::kTaskKdWalk, std::move(input));
}

// What the pinned walk must do with one ray: its answer, and for a closest hit the tests in order
// and the box test and plane steps it counted.
std::string walkProblem(const WalkRay& r, const worker::RawQuery& got, const std::vector<uint32_t>& tested) {
    if (r.occlusionQuery) return (got.prim != 0) == (r.prim != 0) ? "" : std::string("expected ") + (r.prim ? "occluded" : "not occluded") + ", got the opposite";
    std::string problems;
    auto add = [&](const std::string& p) { problems += (problems.empty() ? "" : "; ") + p; };
    if (got.prim != r.prim || (r.prim != kNoHit && got.t != r.t))
        add("expected " + (r.prim == kNoHit ? std::string("a miss") : "prim " + std::to_string(r.prim) + " at t = " + formatNumber(r.t)) + ", got " +
            (got.prim == kNoHit ? std::string("a miss") : "prim " + std::to_string(got.prim) + " at t = " + formatNumber(got.t)));
    if (tested != r.tested) add("tested " + listText(tested) + " instead of " + listText(r.tested) + " (the leaves' order, the stop rule, the mailbox)");
    if (got.nodeVisits != r.steps)
        add(std::to_string(got.nodeVisits) + " box tests and plane steps instead of " + std::to_string(r.steps) + " (one hitsBox, one countPlaneStep per interior node)");
    return problems;
}

TestGroup walkGroup() {
    auto cases = std::make_shared<std::vector<WalkCase>>(walkCases());
    TestGroup group{kA5, "a5 walks on trees built by hand", {}, {}};
    for (const WalkCase& c : *cases)
        for (worker::QueryKind kind : {worker::QueryKind::Closest, worker::QueryKind::Occluded}) {
            std::vector<Ray> rays;
            for (const WalkRay& r : c.rays)
                if (r.occlusionQuery == (kind == worker::QueryKind::Occluded)) rays.push_back(r.ray);
            group.phases.push_back(walkPhase(c, kind, rays));
        }
    group.score = [cases](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA5, "a5/traversal/walk");
        CaseTally tally(result);
        size_t phase = 0;
        for (const WalkCase& c : *cases)
            for (bool occlusion : {false, true}) {
                const PhaseOutcome& outcome = run.phases[phase++];
                if (failedPhaseResult(outcome, result)) {
                    results.push_back(std::move(result));
                    return;
                }
                ByteReader in(outcome.data);
                for (const WalkRay& r : c.rays) {
                    if (r.occlusionQuery != occlusion) continue;
                    auto answer = in.get<worker::RawQuery>();
                    auto n = in.get<uint32_t>();
                    if (n > worker::kMaxListedTests) throw WireError("a list of tests longer than the limit");
                    std::vector<uint32_t> tested(n);
                    for (uint32_t& prim : tested) prim = in.get<uint32_t>();
                    tally.record("[" + c.id + "] " + r.id + ", " + describeRay(r.ray), walkProblem(r, answer, tested));
                }
            }
        tally.finish();
        results.push_back(std::move(result));
    };
    return group;
}

// --- The whole tree -------------------------------------------------------------------------------

std::optional<KdTree> readTree(const PhaseOutcome& outcome, size_t primCount, std::string* problem) {
    try {
        ByteReader in(outcome.data);
        KdTree tree;
        auto frame = in.get<worker::KdTreeFrame>();
        tree.bounds = frame.bounds;
        tree.maxDepth = frame.maxDepth;
        // More nodes or references than kKdMaxIndex cannot be addressed; a correct tree over
        // these scenes has far fewer.
        tree.nodes = in.getVector<KdNode>(std::min<uint64_t>(kKdMaxIndex, 200 * primCount + 16));
        tree.primIndices = in.getVector<uint32_t>(std::min<uint64_t>(kKdMaxIndex, 200 * primCount + 16));
        return tree;
    } catch (const WireError& e) {
        *problem = std::string("the build sent malformed results: ") + e.what();
        return std::nullopt;
    }
}

// A build phase: the scene, then what writeOptions adds.
template <typename WriteOptions>
std::function<ChildPhase(const Scene&)> buildPhase(const std::string& stub, const std::string& entry, const char* task,
                                                   WriteOptions writeOptions) {
    return [=](const Scene& scene) {
        ByteWriter input;
        writeScene(scene, input);
        writeOptions(input);
        return makePhase(stub, task, std::move(input), entry);
    };
}

// The KD-tree as the generic structure tests see it, with pbrt-v3's defaults. The build calls
// `entry` first.
StructurePlugin kdPlugin(const std::string& label, worker::KdBuildFunction function, const std::string& stub, const std::string& entry) {
    const KdTreeOptions options;
    StructurePlugin plugin;
    plugin.assignment = kA5;
    plugin.label = label;
    plugin.drawing = "kdtree";
    plugin.draw = drawPlanes;
    plugin.traceAccelerator = function == worker::KdBuildFunction::NlogN ? "kdtree:build=nlogn" : "kdtree:build=sort";
    plugin.build = buildPhase(stub, entry, worker::kTaskKdBuild, [options, function](ByteWriter& input) {
        input.put(options);
        input.put<uint8_t>(static_cast<uint8_t>(function));
    });
    plugin.queryTask = worker::kTaskKdQuery;
    plugin.queries = {{"closest-hits", worker::QueryKind::Closest, kStubClosest}, {"any-hits", worker::QueryKind::Occluded, kStubOccluded}};
    plugin.given = givenKdTree;
    plugin.givenQueryTask = worker::kTaskKdGivenQuery;
    plugin.check = [options](const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope) {
        StructureReport report;
        std::string problem;
        auto tree = readTree(build, primBounds.size(), &problem);
        if (!tree) {
            report.problems.push_back(problem);
            return report;
        }
        KdTreeReport check = checkKdTree(*tree, primBounds, options);
        report.problems = check.problems;
        report.problemCount = check.problemCount;
        report.summary = std::to_string(tree->nodes.size()) + " nodes, " + std::to_string(check.leaves) + " leaves, depth " +
                         std::to_string(check.depth) + " (limit " + std::to_string(check.maxDepth) + "), " + std::to_string(check.references) +
                         " references (" + formatNumber(double(check.references) / double(std::max<size_t>(1, primBounds.size()))) +
                         " per primitive); every node as the rules make it";
        if (report.problems.empty()) {
            report.cost = kdTreeCost(*tree, options.costs);
            // Only a valid tree: the drawing follows its child links, which may loop in another.
            report.view = kdTreeStructureView(*tree);
        }
        return report;
    };
    return plugin;
}

StructurePlugin bspPlugin() {
    const BspOptions options;
    StructurePlugin plugin;
    plugin.assignment = kA5;
    plugin.label = "bsp";
    plugin.traceAccelerator = "bsp";
    plugin.build = buildPhase(kStubBsp, kStubBsp, worker::kTaskBspBuild, [options](ByteWriter& input) { input.put(options); });
    plugin.queryTask = worker::kTaskBspQuery;
    plugin.queries = {{"closest-hits", worker::QueryKind::Closest, kStubBspClosest}, {"any-hits", worker::QueryKind::Occluded, kStubBspOccluded}};
    // Judged by its hits only: the structure test says what was built.
    plugin.check = [](const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope) {
        StructureReport report;
        try {
            ByteReader in(build.data);
            auto nodes = in.get<uint64_t>(), references = in.get<uint64_t>();
            report.summary = std::to_string(nodes) + " nodes, " + std::to_string(references) + " references (" +
                             formatNumber(double(references) / double(std::max<size_t>(1, primBounds.size()))) + " per primitive)";
        } catch (const WireError& e) {
            report.problems.push_back(std::string("the build sent malformed results: ") + e.what());
        }
        return report;
    };
    return plugin;
}

}  // namespace

std::vector<TestGroup> a5Groups(GradingContext& context) {
    std::vector<TestGroup> groups;
    groups.push_back(sahGroup());
    groups.push_back(eventsGroup());
    groups.push_back(splitGroup());
    groups.push_back(leafGroup());
    groups.push_back(childOrderGroup());
    groups.push_back(walkGroup());
    StructurePlugin kdtree = kdPlugin("kdtree", worker::KdBuildFunction::Sort, kStubBuild, kEntryBuild);
    kdtree.cost = CostTest{"sah-cost", "SAH cost", 1e-12, "within 1e-12 relative"};
    for (TestGroup& g : structureGroups(kdtree, context)) groups.push_back(std::move(g));
    // The stadium: the depth limit of pbrt's rule against a small model in a large box.
    auto stadium = prepareScene(teapotInAStadium(context.modelsDir), context.seed);
    groups.push_back(structureSceneGroup(kdtree, stadium, context));
    // Beyond the lecture, worth no points: the O(N log N) build must give the same trees, and the
    // BSP autopartition the right hits.
    StructurePlugin nlogn = kdPlugin("nlogn", worker::KdBuildFunction::NlogN, kStubBuildNlogN, kStubBuildNlogN);
    StructurePlugin bsp = bspPlugin();
    for (const auto& scene : hitSetScenes(context).list) {
        groups.push_back(structureSceneGroup(nlogn, scene, context));
        // The BSP is judged by its hits alone: on the timed scene it gets an untimed copy, since
        // an autopartition of a closed mesh is slow by nature (docs/bsp.md).
        bool timed = scene->bruteForceSecondsPerRay > 0.0;
        groups.push_back(structureSceneGroup(bsp, timed ? prepareScene(scene->test, context.seed) : scene, context));
    }
    // Every scene rendered through the structure.
    for (TestGroup& g : imageGroups(context, {"a5", "kdtree:build=sort", "the renderer with --accel kdtree:build=sort (a0 + a5 functions)", kEntryBuild}))
        groups.push_back(std::move(g));
    return groups;
}

}  // namespace rtlab::grader
