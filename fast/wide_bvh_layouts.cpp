// Registers the wide BVHs (bvh4, bvh8) in every executable that links rtlab_fast: the same
// tree as the binary bvh, traversed four or eight children at a time. rtlab_fast is an object
// library, so this file's registrations are always linked in.
#include "fast/wide_bvh_accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/bvh_accelerator.h"
#include "framework/interface/a1_bvh.h"

namespace rtlab {
namespace {

template <int W>
AcceleratorType wideBvhType(const char* name, const char* description, int speedRank) {
    return {name, description, bvhTreeOptions(),
            [](const AcceleratorParameters& p) {
                // The student's tree is built on one thread, and so are its packets.
                return std::make_unique<WideBvhAccelerator<W>>(
                    [options = bvhOptionsFrom(p)](const PrimitiveSet& prims) {
                        return collapseToWide<W>(buildBvh(buildPrimitivesOf(prims), options));
                    },
                    1);
            },
            {std::string(name) + "-sah", std::string(name) + "-buckets:12"}, speedRank};
}

// Eight lanes fill one AVX register; without AVX they run as two SSE halves and the four-wide
// tree renders faster (docs/performance.md#the-renderer). A portable build running its AVX2
// copy of the traversal (wide_bvh_dispatch.h) has AVX.
bool eightLanesFit() {
#if defined(__AVX__)
    return true;
#else
    return usesAvx2Copy();
#endif
}

const AcceleratorRegistration kFourWide{
    wideBvhType<4>("bvh4", "the bvh tree four wide (fast/)", eightLanesFit() ? 1 : 2)};
const AcceleratorRegistration kEightWide{
    wideBvhType<8>("bvh8", "the bvh tree eight wide (fast/)", eightLanesFit() ? 2 : 1)};

}  // namespace
}  // namespace rtlab
