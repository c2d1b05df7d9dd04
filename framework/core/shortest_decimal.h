// Numbers as text that parses back to exactly the value we hold: the shortest decimal that
// round-trips (std::to_chars), for the scene files we write for other programs (POV-Ray SDL,
// Blender's Python), which read every literal as a double.
#pragma once

#include <string>

namespace rtlab {

// Exact for a double (and for a float widened to double). Throws rtlab::Error for inf and NaN,
// which neither POV-Ray nor Python reads back as a literal; `what` names the export.
std::string shortestDecimal(double value, const char* what);

// The shortest decimal that rounds back to the same float32 (at most max_digits10 = 9
// digits): for programs that store float32 (POV-Ray's mesh2, Blender's meshes), so they hold
// our exact vertex values.
std::string shortestDecimal32(float value, const char* what);

}  // namespace rtlab
