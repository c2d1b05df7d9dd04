// The accelerator `rtlab render` builds (docs/rendering.md): the one --accel names, or the
// default, which is built with a2's SAH buckets. A student who has finished a0 and a1 but not
// a2 would stop in an a2 stub on every render; without --accel, render then builds a1's
// bvh-median instead and says so in one line, naming the flag.
#pragma once

#include "framework/accel/accelerator.h"

#include <functional>
#include <memory>
#include <ostream>

namespace rtlab::cli {

inline constexpr const char* kRenderFallbackAccelerator = "bvh-median";

using AcceleratorFactory = std::function<std::unique_ptr<Accelerator>(const AcceleratorSpec&)>;

// Builds make(spec) over primitives. When the build throws NotImplemented from an a2 stub and
// spec was not given on the command line, writes the note to notes, sets spec.name to
// kRenderFallbackAccelerator and builds that. Anything else propagates (an a0 or a1 stub too:
// no accelerator avoids those).
std::unique_ptr<Accelerator> buildRenderAccelerator(AcceleratorSpec& spec, bool specGiven, const PrimitiveSet& primitives,
                                                    const AcceleratorFactory& make, std::ostream& notes);

}  // namespace rtlab::cli
