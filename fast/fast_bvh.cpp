// Registers fastbvh: the wide BVH built by fast/'s own builder (wide_bvh_builder.h) and traversed
// as bvh4 and bvh8 are (wide_bvh_accelerator.h). It is the fastest structure rtlab-solution has,
// so `rtlab-solution render` uses it unless told otherwise.
#include "fast/wide_bvh_accelerator.h"
#include "fast/wide_bvh_builder.h"
#include "framework/accel/accelerator_registry.h"

#include <cstdio>

namespace rtlab {
namespace {

// Eight lanes fill one AVX register; without AVX an eight-wide node runs as two SSE halves.
// A portable build running its AVX2 copy of the traversal (wide_bvh_dispatch.h) has AVX.
const char* defaultWidth() {
#if defined(__AVX__)
    return "8";
#else
    return usesAvx2Copy() ? "8" : "4";
#endif
}

template <int W>
std::unique_ptr<Accelerator> wideBvhOf(const WideBvhBuildOptions& options) {
    return std::make_unique<WideBvhAccelerator<W>>(
        [options](const PrimitiveSet& prims) { return buildWideBvh<W>(prims.allBounds(), options); }, options.threads);
}

std::string numberText(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Parses fastbvh's options (validated against their ranges by the registry).
std::unique_ptr<Accelerator> createFastBvh(const AcceleratorParameters& p) {
    WideBvhBuildOptions options;
    options.maxLeaf = p.integer("leaf");
    options.bins = p.integer("bins");
    options.packetCost = static_cast<float>(p.number("Ci"));
    options.threads = p.integer("threads");
    return p.word("width") == "4" ? wideBvhOf<4>(options) : wideBvhOf<8>(options);
}

AcceleratorType fastBvhType() {
    const WideBvhBuildOptions defaults;
    return {"fastbvh",
            "a wide BVH from fast/'s own builder: binned SAH on all axes and threads, leaves priced by "
            "their packets of four triangles (fast/)",
            {
                {"width", "children per node", defaultWidth(), 0, 0, false, {"4", "8"}},
                {"leaf", "largest leaf (triangles)", std::to_string(defaults.maxLeaf), 1, 1024, true, {}},
                {"bins", "SAH bins per axis", std::to_string(defaults.bins), 2, kMaxSahBins, true, {}},
                {"Ci", "cost of a packet test, in node tests", numberText(defaults.packetCost), 0.125, 8, false, {}},
                {"threads", "build threads (0: every CPU the process may use)", "0", 0, 256, true, {}},
            },
            createFastBvh,
            {"fastbvh:width=4", "fastbvh:width=8"},
            3};
}

const AcceleratorRegistration kFastBvh{fastBvhType()};

}  // namespace
}  // namespace rtlab
