// The image tests of an assignment whose structure renders the scenes (docs/grading.md, "What
// is tested"): every scene of scenes/ rendered by the worker with the assignment's accelerator,
// compared with its POV-Ray reference.
#pragma once

#include "grader/engine/test_group.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct ImageConfig {
    std::string assignment;   // "a1": tests named a1/images/<scene>
    std::string accelerator;  // the registry name the worker renders with: "bvh-median"
    std::string stub;         // named in verdicts
    std::string entry;        // the stub the render calls first: the structure's build (ChildPhase::entry)
};

std::vector<TestGroup> imageGroups(GradingContext& context, const ImageConfig& config);

}  // namespace rtlab::grader
