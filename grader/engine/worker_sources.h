// The student files a worker was built from, by content: a manifest beside the worker
// (<worker>.sources), one line "<SHA-256> <folder>/<file>" per source file of the tree it was
// built from (assignments/ or solutions/). The build that links a worker writes it:
// grader/worker_sources.cmake for rtlab-worker and rtlab-worker-solution, buildSubmission for a
// submission's worker.
//
// A phase whose stub lives in a file the worker holds exactly as committed is reported not
// started without running (sandbox.h, StubVerdicts): every committed stub throws NotImplemented
// on entry, whatever its input, so running it could only give the same verdict later. A missing
// or stale manifest costs only that shortcut, and what one claims can only take points away:
// a phase it calls committed is not started, which earns nothing.
#pragma once

#include <map>
#include <set>
#include <string>

namespace rtlab::grader {

// "<worker>.sources"
std::string workerSourcesPath(const std::string& workerPath);

// Writes the manifest of workerPath for the .cpp files under root (root/<folder>/<file>).
void writeWorkerSources(const std::string& root, const std::string& workerPath);

// The stubs (StubTable::name of every registered assignment) whose file the worker holds as
// committed. committed: repository path ("assignments/a0_intersect/ray_box.cpp") -> contents,
// from git's HEAD; empty when unknown, and then so is the result.
std::set<std::string> unstartedStubs(const std::map<std::string, std::string>& committed, const std::string& workerPath);

}  // namespace rtlab::grader
