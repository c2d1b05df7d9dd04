// The student's walk of each failing case's rays, for the report's viewer pages
// (docs/viewer.md#from-the-report). After every test is scored, one more sandboxed run builds
// each case's structure with the student's code under its registry name (FailedCase::
// traceAccelerator) and traces its rays; the traces come back as untrusted bytes, read with the
// bounded decoder (framework/accel/traversal_trace_format.h). A trace that cannot be had (the
// code threw, crashed, timed out, or sent something malformed) leaves the ray without one and
// says why in the case's notes; scores are never touched.
#pragma once

#include "grader/engine/sandbox.h"
#include "grader/engine/test_result.h"

#include <vector>

namespace rtlab::grader {

void recordStudentTraces(std::vector<TestResult>& tests, const WorkerSpec& worker);

}  // namespace rtlab::grader
