// The instruction set of one copy of the SIMD code. fast/'s traversal is compiled twice in a
// portable build: for the build's own target (SSE2 on x86-64) and, in
// wide_bvh_traversal_avx2.cpp, with -mavx2, chosen at run time by the CPU (wide_bvh_dispatch.h).
// The two copies of every inline function they share must not meet at link time, where the
// linker keeps one of each name: AVX2 code would then run on CPUs without it. So the code both
// copies compile (simd.h, ShearedRay, the traversal) sits between RTLAB_ISA_NAMESPACE_BEGIN and
// _END: an inline namespace of its own name in the AVX2 copy, nothing in the other; a build test
// (fast/check-isa-copy) checks that the AVX2 object defines no other inline function.
#pragma once

#if defined(RTLAB_FAST_AVX2_COPY)
#define RTLAB_ISA_NAMESPACE_BEGIN inline namespace avx2 {
#define RTLAB_ISA_NAMESPACE_END }
#else
#define RTLAB_ISA_NAMESPACE_BEGIN
#define RTLAB_ISA_NAMESPACE_END
#endif
