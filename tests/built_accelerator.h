// The accelerator a spec names, built over prims: the first step of every test that compares
// structures.
#pragma once

#include "framework/accel/accelerator.h"

#include <memory>

namespace rtlab {

inline std::unique_ptr<Accelerator> builtAccelerator(const AcceleratorSpec& spec, const PrimitiveSet& prims) {
    auto accelerator = makeAccelerator(spec);
    accelerator->build(prims);
    return accelerator;
}

}  // namespace rtlab
