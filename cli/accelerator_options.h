// The accelerator flags that render and hits share: --accel, --max-leaf, --traversal and
// --sah-axes (docs/conventions.md).
#pragma once

#include "framework/accel/accelerator.h"

#include <CLI/CLI.hpp>

#include <string>

namespace rtlab::cli {

// Adds the flags to command: --accel writes spec's name, the others set the BVH options they
// name (leaf, traversal, axes) as typed flag settings of spec. The help of --accel is accelWhat
// ("Accelerator", or what else the command accepts) followed by the names this executable knows.
void addAcceleratorOptions(CLI::App* command, AcceleratorSpec& spec, const std::string& accelWhat);

}  // namespace rtlab::cli
