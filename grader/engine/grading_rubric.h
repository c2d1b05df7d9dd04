// The rubric a grading run applies (docs/grading.md, "The rubric"), loaded once per run: an
// instructor's --rubric file alone when one is given; otherwise grader/rubric.json with the
// part of every registered assignment, grader/<its folder>/rubric.json, read before its rules.
#pragma once

#include "grader/engine/rubric.h"

#include <string>

namespace rtlab::grader {

// rubricPath empty: the repository's rubric at sourceDir with every assignment's part.
Rubric loadGradingRubric(const std::string& sourceDir, const std::string& rubricPath);

}  // namespace rtlab::grader
