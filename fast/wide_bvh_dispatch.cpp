#include "fast/wide_bvh_dispatch.h"

#include <cstdlib>
#include <cstring>

namespace rtlab {

bool usesAvx2Copy() {
#if defined(RTLAB_FAST_HAS_AVX2_COPY) && defined(__OPTIMIZE__)
    static const bool chosen = [] {
        const char* isa = std::getenv("RTLAB_FAST_ISA");
        if (isa && std::strcmp(isa, "baseline") == 0) return false;
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return chosen;
#else
    return false;
#endif
}

template <int W>
WideTraversal<W> wideTraversal(bool spheres) {
    if (usesAvx2Copy()) return avx2WideTraversal<W>(spheres);
    if (spheres) return {closestHit<W, true>, anyHit<W, true>};
    return {closestHit<W, false>, anyHit<W, false>};
}

template WideTraversal<4> wideTraversal<4>(bool);
template WideTraversal<8> wideTraversal<8>(bool);

}  // namespace rtlab
