// The bytes of a TraversalTrace (framework/interface/traversal_trace.h), so a trace can cross a
// process boundary (a grader worker, rtlab-solution run beside rtlab) and be read back safely.
// A trace that comes from student code is untrusted: decodeTraversalTrace reads it like
// grader/wire/wire_format.h reads a worker's results, with every length bounded before anything is
// allocated and every field checked, and throws TraceFormatError on the first problem, never
// crashing and never returning a trace that breaks its own rules.
//
// Layout, little-endian, 24-byte header then two plain arrays:
//   u32 magic "RTtr"  u16 version (1)  u16 zero
//   u32 op count  u32 box count  u64 dropped operations
//   op count x TraceOp (16 bytes: u8 kind, u8 hit, u16 zero, u32 index, f32 t, f32 tFar)
//   box count x 6 f32 (lower xyz, upper xyz)
// Rules the decoder enforces: kind < kTraceOpKinds; hit is 0 or 1 (and 0 for a cell step, plane
// step, leaf entry or mailbox repeat); the k-th box test has index k and there are as many
// box tests as boxes; cell and plane steps have index kTraceNoIndex; the byte count is exact.
// Floats may be any value (a student's NaN is shown as NaN); the viewer checks them before
// drawing.
#pragma once

#include "framework/interface/traversal_trace.h"

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace rtlab {

struct TraceFormatError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr uint32_t kTraceMagic = 0x72745452;  // "RTtr" read as little-endian bytes
inline constexpr uint16_t kTraceVersion = 1;
inline constexpr size_t kTraceHeaderBytes = 24;

std::vector<uint8_t> encodeTraversalTrace(const TraversalTrace& trace);
// maxOps bounds what a forged header can make the reader allocate.
TraversalTrace decodeTraversalTrace(std::span<const uint8_t> bytes, uint32_t maxOps = kTraceDefaultCapacity);

// The same through a file; errors name the file ("FILE: problem").
void writeTraversalTraceFile(const std::string& path, const TraversalTrace& trace);
TraversalTrace readTraversalTraceFile(const std::string& path, uint32_t maxOps = kTraceDefaultCapacity);

}  // namespace rtlab
