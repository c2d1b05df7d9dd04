// Makes the wide BVHs --accel names (bvh4-*, bvh8-*) of every executable that links rtlab_fast.
// rtlab_fast is an object library, so this file's registration is always linked in.
#include "fast/wide_bvh_accelerator.h"
#include "framework/accel/bvh_layouts.h"

namespace rtlab {
namespace {

template <int W>
std::unique_ptr<Accelerator> makeWideBvh(const BvhOptions& options) {
    return std::make_unique<WideBvhAccelerator<W>>(options);
}

const BvhLayoutRegistration kFourWide{{"bvh4", "the same tree four wide, fast/", makeWideBvh<4>}};
const BvhLayoutRegistration kEightWide{{"bvh8", "the same tree eight wide, fast/", makeWideBvh<8>}};

}  // namespace
}  // namespace rtlab
