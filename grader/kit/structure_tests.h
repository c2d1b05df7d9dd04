// The generic accelerator tests (docs/grading.md#what-is-tested), for any structure that plugs
// in with a build phase, a query task and a check of what the build returned. On every hit-set
// scene: structure, closest hits and any hits (plus any other traversal the plugin grades)
// against the oracle, and efficiency on the timed scene; where the plugin has them, a cost
// recomputed by the grader against the reference data and the order of the primitives a
// traversal tests. Over the stress catalogue's degenerate scenes: degenerate-inputs. Tests are
// named <assignment>/<label>/<test>; reference entries <label>/<scene>.
#pragma once

#include "framework/accel/structure_drawing.h"
#include "grader/kit/accelerator_checks.h"
#include "grader/kit/given_structure.h"
#include "grader/kit/stress_scenes.h"
#include "grader/kit/visit_order_verdict.h"

#include <functional>
#include <optional>

namespace rtlab::grader {

// What the scenes a structure is checked on allow: the degenerate ones hold NaN and infinite
// boxes, so a check may relax what it asks of bounds there.
enum class CheckScope { HitSetScene, DegenerateScene };

// What a plugin's check makes of a build phase's output.
struct StructureReport {
    std::vector<std::string> problems;  // empty: the structure is valid (the first few)
    size_t problemCount = 0;            // all of them, when more than listed
    std::string summary;                // one line for a valid one: sizes, references per primitive
    // The structure as the viewer draws it, also when invalid, as far as it can be read without
    // following an index out of range (unset: it cannot); the report's viewer links show it.
    std::optional<StructureView> view;
    std::optional<std::array<int, 3>> gridResolution;  // a uniform grid's view: its cells per axis
    // Set for a valid structure by plugins that have these tests:
    std::optional<double> cost;  // the grader's own cost of the structure (its SAH cost)
    // Judges the primitives each ray's closest-hit traversal tested, in order, on this structure.
    std::function<VisitOrderVerdict(const Scene& scene, const std::vector<Ray>& rays,
                                    const std::vector<std::vector<uint32_t>>& tested)>
        judgeVisits;
};

// One traversal graded by hit sets: its test name, the query kind the plugin's query task
// answers, and the stub named in verdicts.
struct QueryTest {
    std::string name;  // "closest-hits", "recursive-hits", "any-hits"
    worker::QueryKind kind;
    std::string stub;
};

struct CostTest {
    std::string name;        // "sah-cost"
    std::string what;        // "SAH cost", in verdicts
    double tolerance = 0.0;  // relative to the reference value
    std::string rule;        // the tolerance in words for verdicts: "within 1e-4 relative"
};

struct StructurePlugin {
    std::string assignment;  // "a3"
    std::string label;       // "grid"
    std::string drawing;     // the structure's name in the report's viewer pages ("bvh")
    // How those pages draw the view: the function the registry entry names as its draw
    // (structure_drawing.h), named here because rtlab-grader does not link the registry.
    StructureDrawer draw = nullptr;
    // The registry name whose accelerator builds this structure with the student's code, so the
    // report's viewer pages can show the student's walk of a failing ray ("bvh:split=median").
    std::string traceAccelerator;
    // The build phase: the scene in, the structure the student's code built out.
    std::function<ChildPhase(const Scene& scene)> build;
    // The worker task answering `u8 QueryKind, [Ray]` with one RawQuery per ray, and the
    // traversals it grades: a closest-hit one first, and an any-hit one.
    std::string queryTask;
    std::vector<QueryTest> queries;
    std::function<StructureReport(const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope scope)> check;
    std::optional<CostTest> cost;
    // The worker task listing, per ray of `[Ray]`, the primitives the closest-hit traversal
    // tests (u32 n, u32 prim[n]), and the stub named in verdicts; empty: no visit-order test.
    std::string visitsTask;
    std::string visitsStub;
    // The traversals again, on a structure the grader built (given_structure.h): its maker and
    // the worker task answering `structure, u8 QueryKind, [Ray]`. Unset: not graded this way.
    std::function<GivenStructure(const Scene& scene, uint64_t key)> given;
    std::string givenQueryTask;
    // Degenerate scenes this structure is not asked to build, with the reason in a comment
    // where the plugin is made (70000 identical triangles fill every cell of a grid).
    std::vector<std::string> skipDegenerate;
};

// The tests above on every hit-set scene, then degenerate-inputs.
std::vector<TestGroup> structureGroups(const StructurePlugin& plugin, GradingContext& context);
// The hit-set tests on one scene (a3's teapot in a stadium joins the hit-set scenes this way).
TestGroup structureSceneGroup(const StructurePlugin& plugin, std::shared_ptr<PreparedScene> scene, GradingContext& context);

}  // namespace rtlab::grader
