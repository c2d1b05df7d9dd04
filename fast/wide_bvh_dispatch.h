// Which copy of the wide BVH's traversal runs (fast/isa.h): the AVX2 one where the build's own
// target lacks AVX2 and the CPU has it, else the build's. RTLAB_FAST_ISA=baseline in the
// environment keeps the build's copy, for its tests and for the instruction counts of
// bench/check-instructions-per-ray, which must not depend on the CPU.
#pragma once

#include "fast/wide_bvh_traversal.h"

namespace rtlab {

template <int W>
struct WideTraversal {
    Hit (*closestHit)(const WideBvhArrays<W>&, const Ray&, TraversalStats&);
    bool (*anyHit)(const WideBvhArrays<W>&, const Ray&, TraversalStats&);
};

// The traversal for a scene with or without spheres, on this CPU.
template <int W>
WideTraversal<W> wideTraversal(bool spheres);

// Whether wideTraversal chooses the AVX2 copy: built, on a CPU that has AVX2, not turned off.
bool usesAvx2Copy();

// The AVX2 copy's traversal (wide_bvh_traversal_avx2.cpp), only where it is built.
template <int W>
WideTraversal<W> avx2WideTraversal(bool spheres);

}  // namespace rtlab
