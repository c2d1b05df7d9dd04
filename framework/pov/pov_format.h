// Numbers and vectors as POV-Ray SDL text, written so that POV-Ray parses back exactly the
// values we hold: the shortest decimal that round-trips (std::to_chars). POV-Ray reads every
// literal as a double.
#pragma once

#include "framework/core/vec.h"

#include <string>

namespace rtlab::pov {

// Exact for a double (and for a float widened to double): for double-precision objects
// (triangle, sphere, camera, lights).
std::string number(double value);
std::string vector(const DVec3& v);  // "<x,y,z>"

// The shortest decimal that rounds back to the same float32 (at most max_digits10 = 9
// digits): for mesh2, which stores float32, so POV-Ray holds our exact vertex values.
std::string number32(float value);
std::string vector32(const Vec3& v);

}  // namespace rtlab::pov
