// The report's viewer cases (grader/engine/failed_case.h) of the tests that judge rays: a wrong
// closest or any hit, a walk out of order. Each holds the ray, the student's answer and the
// oracle's, and the scene, shared with the grading run rather than copied.
#pragma once

#include "grader/engine/failed_case.h"
#include "grader/kit/accelerator_checks.h"

#include <memory>
#include <string>
#include <vector>

namespace rtlab::grader {

// The scene of a prepared scene, kept alive by it.
std::shared_ptr<const Scene> sharedScene(const std::shared_ptr<PreparedScene>& prepared);

// A wrong closest hit of `judge`'s ray `wrong.index`: the student's prim and t against the
// oracle's closest hit.
FailedCase closestHitCase(const std::shared_ptr<PreparedScene>& scene, HitJudge& judge, const Ray& ray, const WrongRay& wrong,
                          const worker::RawQuery& answer, const std::string& title);
// A wrong any-hit answer: blocked or not, against the opposite.
FailedCase anyHitCase(const std::shared_ptr<PreparedScene>& scene, const Ray& ray, const WrongRay& wrong, bool blocked,
                      const std::string& title);

// A list of primitives tested (or leaves entered) as a trace the viewer steps through.
TraversalTrace visitTrace(const std::vector<uint32_t>& visits, TraceOpKind kind);

}  // namespace rtlab::grader
