// The one list of graded assignments. Adding an assignment is its folders (assignments/,
// solutions/, its interface header, its grader tests and rubric part, its docs page) and one
// entry, with its include, in grader/assignment_registry.cpp (docs/adding-an-assignment.md).
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct Assignment {
    std::string id;     // "a3": the prefix of its test names and rubric rules
    std::string title;  // "uniform grid and 3D-DDA"
    std::vector<TestGroup> (*groups)(GradingContext& context);
    const StubTable& (*stubs)();  // its student files' stubs, as they name themselves
    // The folders of assignments/ its tests call: those it builds on (every structure's
    // traversal calls a0's intersections), then its own, last, which is also the name of its
    // folder in grader/ (its tests, worker tasks and rubric part).
    std::vector<std::string> folders;
};

const std::vector<Assignment>& assignments();
const Assignment* findAssignment(const std::string& id);
// "a0, a1, a2, a3": for help texts and errors.
std::string assignmentIds();

}  // namespace rtlab::grader
