// The wide BVH's traversal compiled with -mavx2 (fast/CMakeLists.txt), for a portable build run
// on a CPU that has AVX2 (wide_bvh_dispatch.h). Without -mfma, so the arithmetic, and every
// hit, is the build's own copy's to the bit.
//
// Only in optimised builds: without optimisation GCC calls the shared headers' inline functions
// (GLM's, PrimitiveSet's) instead of inlining them, and their AVX2 copies could be the ones the
// linker keeps (fast/isa.h). wide_bvh_dispatch.cpp asks the same question.
#define RTLAB_FAST_AVX2_COPY
#include "fast/wide_bvh_dispatch.h"

#if defined(__OPTIMIZE__)
namespace rtlab {

template <int W>
WideTraversal<W> avx2WideTraversal(bool spheres) {
    if (spheres) return {avx2::closestHit<W, true>, avx2::anyHit<W, true>};
    return {avx2::closestHit<W, false>, avx2::anyHit<W, false>};
}

template WideTraversal<4> avx2WideTraversal<4>(bool);
template WideTraversal<8> avx2WideTraversal<8>(bool);

}  // namespace rtlab
#endif
