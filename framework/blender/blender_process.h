// Running Blender headless (`blender -b --factory-startup`) under a time limit
// (framework/external/external_process.h). The executable is `blender` on PATH, or the one the
// environment variable RTLAB_BLENDER names (e.g. a Blender 3.4.1 unpacked elsewhere).
#pragma once

#include "framework/external/temporary_directory.h"

#include <string>
#include <vector>

namespace rtlab {

// The longest a Blender run may take before it is killed: a 160x120 reference at 512 samples
// takes about half a minute on two loaded cores (docs/verification.md#6-blender-cycles-references).
inline constexpr double kBlenderTimeLimitSeconds = 1200.0;

// "blender", or $RTLAB_BLENDER when it is set and not empty.
std::string blenderProgram();

// Runs `blender -b --factory-startup --python-exit-code 1 arguments...` in `work` with its log
// in work/blender.log. When Blender cannot be started, exits non-zero or overruns the limit,
// keeps the folder and throws rtlab::Error with one line: `what` was being done, Blender's last
// error line, the log path; for a missing Blender, how to install it.
void runBlenderOrThrow(const std::vector<std::string>& arguments, TemporaryDirectory& work, const std::string& what,
                       double timeLimitSeconds = kBlenderTimeLimitSeconds);

// The first line `blender --version` prints, e.g. "Blender 3.4.1".
std::string blenderVersion();

}  // namespace rtlab
