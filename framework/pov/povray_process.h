// Running the `povray` executable headless, from a working folder it may write in (Debian's
// povray.conf lets POV-Ray write only in its current directory and the system temp folder),
// under a time limit (framework/external/external_process.h).
#pragma once

#include "framework/external/temporary_directory.h"

#include <string>
#include <vector>

namespace rtlab {

// The longest a povray run may take: a 320x240 reference takes about a second and 10^5
// trace() rays about 3 s, so this only ends a POV-Ray that hangs.
inline constexpr double kPovrayTimeLimitSeconds = 600.0;

// Runs povray in `work` with its log in work/povray.log. When it exits non-zero or overruns
// the time limit, keeps the folder and throws rtlab::Error with one line: `what` was being
// done, POV-Ray's first error line and the log path.
void runPovrayOrThrow(const std::vector<std::string>& arguments, TemporaryDirectory& work,
                      const std::string& what);

// The version line `povray --version` prints, e.g. "POV-Ray 3.7.0.10.unofficial".
std::string povrayVersion();

}  // namespace rtlab
