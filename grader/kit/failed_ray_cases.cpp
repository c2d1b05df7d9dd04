#include "grader/kit/failed_ray_cases.h"

namespace rtlab::grader {

std::shared_ptr<const Scene> sharedScene(const std::shared_ptr<PreparedScene>& prepared) {
    // The aliasing constructor: points at the scene, owns the prepared scene it lives in.
    return std::shared_ptr<const Scene>(prepared, &prepared->test.scene);
}

FailedCase closestHitCase(const std::shared_ptr<PreparedScene>& scene, HitJudge& judge, const Ray& ray, const WrongRay& wrong,
                          const worker::RawQuery& answer, const std::string& title) {
    FailedCase failed;
    failed.title = title;
    failed.notes.push_back(wrong.problem);
    failed.scene = sharedScene(scene);
    CaseRay& r = failed.rays.emplace_back();
    r.ray = ray;
    r.label = "ray " + std::to_string(wrong.index);
    r.student = CaseAnswer::closest(answer.prim, answer.t);
    std::optional<HitJudge::Candidate> expected = judge.closestCandidate(wrong.index, ray);
    r.expected = expected ? CaseAnswer::closest(expected->prim, float(expected->t)) : CaseAnswer::closest(kNoHit, kInfinity);
    return failed;
}

FailedCase anyHitCase(const std::shared_ptr<PreparedScene>& scene, const Ray& ray, const WrongRay& wrong, bool blocked,
                      const std::string& title) {
    FailedCase failed;
    failed.title = title;
    failed.notes.push_back(wrong.problem);
    failed.scene = sharedScene(scene);
    CaseRay& r = failed.rays.emplace_back();
    r.ray = ray;
    r.label = "any-hit ray " + std::to_string(wrong.index);
    r.student = CaseAnswer::anyHit(blocked);
    r.expected = CaseAnswer::anyHit(!blocked);  // a yes-or-no answer that was wrong
    return failed;
}

TraversalTrace visitTrace(const std::vector<uint32_t>& visits, TraceOpKind kind) {
    TraversalTrace trace;
    for (uint32_t index : visits) trace.add(TraceOp{kind, 0, 0, index, 0.0f, 0.0f});
    return trace;
}

}  // namespace rtlab::grader
