#include "grader/engine/grading_rubric.h"

#include "grader/engine/assignment_registry.h"

namespace rtlab::grader {

Rubric loadGradingRubric(const std::string& sourceDir, const std::string& rubricPath) {
    if (!rubricPath.empty()) return Rubric::load(rubricPath);
    std::vector<std::string> parts;
    for (const Assignment& a : assignments()) parts.push_back(sourceDir + "/grader/" + a.folders.back() + "/rubric.json");
    return Rubric::load(sourceDir + "/grader/rubric.json", parts);
}

}  // namespace rtlab::grader
