// The generic accelerator tests (docs/grading.md#what-is-tested), for any structure that plugs in
// with a build phase, a query phase and a check of what the build returned: per scene its
// structure, closest hits and any-hits against the oracle, and, on the timed scene, efficiency;
// over the stress catalogue's degenerate scenes, degenerate-inputs. Tests are named
// <assignment>/<label>/<test>.
#pragma once

#include "grader/accelerator_checks.h"

#include <functional>

namespace rtlab::grader {

struct StructureReport {
    std::vector<std::string> problems;  // empty: the structure is valid
    std::string summary;                // one line for a valid one: sizes, references per primitive
};

struct StructurePlugin {
    std::string assignment;  // "a3"
    std::string label;       // "grid"
    std::function<ChildPhase(const Scene& scene)> build;
    std::function<ChildPhase(bool occluded, const std::vector<Ray>& rays)> query;
    std::function<StructureReport(const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds)> check;
};

// The structure, closest-hits, any-hits and (on a timed scene) efficiency tests on one scene.
TestGroup structureSceneGroup(const StructurePlugin& plugin, std::shared_ptr<PreparedScene> scene);

}  // namespace rtlab::grader
