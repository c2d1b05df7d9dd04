#include "grader/a1_bvh/bvh_tests.h"

#include "framework/accel/bvh_accelerator.h"

#include "grader/a1_bvh/a1_tests.h"
#include "grader/a1_bvh/bvh_structure.h"
#include "grader/a1_bvh/visit_order.h"
#include "grader/a1_bvh/given_bvh.h"
#include "grader/wire/scene_codec.h"
#include "grader/kit/structure_tests.h"
#include "grader/a1_bvh/wire/bvh_inputs.h"

namespace rtlab::grader {
namespace {

const std::string kStubOrdered = a1Stubs().name("intersectBvh");
const std::string kStubRecursive = a1Stubs().name("intersectBvhRecursive");
const std::string kStubOccluded = a1Stubs().name("occludedBvh");

std::optional<Bvh> readBvh(const PhaseOutcome& outcome, size_t primCount, std::string* problem) {
    try {
        ByteReader in(outcome.data);
        Bvh bvh;
        bvh.nodes = in.getVector<BvhNode>(4 * primCount + 16);
        bvh.primIndices = in.getVector<uint32_t>(4 * primCount + 16);
        return bvh;
    } catch (const WireError& e) {
        *problem = std::string("the build sent malformed results: ") + e.what();
        return std::nullopt;
    }
}

// The grader's reading of a build: the invariants of bvh_structure.h; on a valid tree, its SAH
// cost and the visit-order judge. On the degenerate scenes, boxes need not be tight (NaN and
// infinite boxes), and no leaf may hold more than maxLeaf primitives without a reason.
StructureReport checkBvh(const BvhConfig& config, const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope scope) {
    StructureReport report;
    std::string problem;
    auto bvh = readBvh(build, primBounds.size(), &problem);
    if (!bvh) {
        report.problems.push_back(problem);
        return report;
    }
    // Numbers only: an index out of range is the viewer's to drop, never followed here.
    report.view = bvhStructureView(*bvh);
    BvhStructureReport invariants = checkBvhStructure(*bvh, primBounds, scope == CheckScope::HitSetScene);
    report.problems = invariants.problems;
    report.problemCount = invariants.problemCount;
    if (!report.problems.empty()) return report;
    if (scope == CheckScope::DegenerateScene) {
        report.problems = oversizedLeaves(*bvh, primBounds, config.options.maxLeaf);
        return report;
    }
    report.summary = std::to_string(bvh->nodes.size()) + " nodes, " + std::to_string(invariants.leaves) + " leaves, depth " +
                     std::to_string(invariants.depth);
    report.cost = graderSahCost(*bvh);
    report.judgeVisits = [tree = std::make_shared<Bvh>(std::move(*bvh))](const Scene& scene, const std::vector<Ray>& rays,
                                                                          const std::vector<std::vector<uint32_t>>& tested) {
        return judgeVisitOrder(*tree, scene, rays, tested);
    };
    return report;
}

// The registry name that builds this configuration's tree with the student's code (the report's
// viewer traces a failing ray through it); options at their defaults are left out.
std::string registryName(const BvhOptions& o) {
    const char* split = o.method == SplitMethod::Median        ? "median"
                        : o.method == SplitMethod::Middle      ? "middle"
                        : o.method == SplitMethod::EqualCounts ? "equal"
                        : o.method == SplitMethod::SahSweep    ? "sah"
                                                               : "buckets";
    const BvhOptions defaults;
    std::string name = std::string("bvh:split=") + split;
    if (o.buckets != defaults.buckets) name += ",B=" + std::to_string(o.buckets);
    if (o.maxLeaf != defaults.maxLeaf) name += ",leaf=" + std::to_string(o.maxLeaf);
    if (o.allAxes) name += ",axes=all";
    return name;
}

StructurePlugin bvhPlugin(const BvhConfig& config) {
    StructurePlugin plugin;
    plugin.assignment = config.assignment;
    plugin.label = config.label;
    plugin.drawing = "bvh";
    plugin.draw = drawBvh;
    plugin.traceAccelerator = registryName(config.options);
    plugin.build = [config](const Scene& scene) {
        ByteWriter input;
        writeScene(scene, input);
        input.put(config.options);
        return makePhase(config.buildStub, worker::kTaskBvhBuild, std::move(input), a1Stubs().name("buildBvh"));
    };
    plugin.queryTask = worker::kTaskBvhQuery;
    plugin.queries.push_back({"closest-hits", worker::QueryKind::Closest, kStubOrdered});
    if (config.recursive) plugin.queries.push_back({"recursive-hits", worker::QueryKind::Recursive, kStubRecursive});
    plugin.queries.push_back({"any-hits", worker::QueryKind::Occluded, kStubOccluded});
    plugin.check = [config](const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope scope) {
        return checkBvh(config, build, primBounds, scope);
    };
    plugin.cost = config.exactSah ? CostTest{"sah-cost", "SAH cost", kExactSahTolerance, "must match exactly"}
                                  : CostTest{"sah-cost", "SAH cost", kSahTolerance, "within 1e-4 relative"};
    if (config.visitOrder) {
        plugin.visitsTask = worker::kTaskBvhVisits;
        plugin.visitsStub = kStubOrdered;
    }
    plugin.given = givenBvh;
    plugin.givenQueryTask = worker::kTaskBvhGivenQuery;
    return plugin;
}

}  // namespace

std::vector<TestGroup> bvhConfigGroups(const BvhConfig& config, GradingContext& context) {
    return structureGroups(bvhPlugin(config), context);
}

}  // namespace rtlab::grader
