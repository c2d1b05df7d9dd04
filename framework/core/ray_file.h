// Rays as text (docs/rendering.md#hits-rtlab-hits; a sample is scenes/rays/sample.rays): one
// ray per line, `ox oy oz dx dy dz` with an optional `tmin tmax` (default 0 and +inf); blank
// lines and `#` comments are ignored. Numbers are read as float with correct rounding, so a
// file written with 9 significant digits reproduces the rays bit for bit.
#pragma once

#include "framework/core/ray.h"

#include <string>
#include <vector>

namespace rtlab {

// Throws rtlab::Error "FILE:LINE: problem" for a malformed line, "FILE: ..." when unreadable.
std::vector<Ray> readRayFile(const std::string& path);

// Writes rays so that readRayFile gives them back exactly (9 significant digits).
void writeRayFile(const std::string& path, const std::vector<Ray>& rays);

}  // namespace rtlab
