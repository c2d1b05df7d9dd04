#include "framework/accel/traversal_trace_format.h"

#include <cstring>
#include <fstream>
#include <iterator>

namespace rtlab {
namespace {

template <typename T>
void put(std::vector<uint8_t>& out, const T& value) {
    size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

template <typename T>
T get(std::span<const uint8_t> bytes, size_t at) {
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    return value;
}

void check(bool ok, const std::string& problem) {
    if (!ok) throw TraceFormatError(problem);
}

}  // namespace

std::vector<uint8_t> encodeTraversalTrace(const TraversalTrace& trace) {
    std::vector<uint8_t> out;
    out.reserve(kTraceHeaderBytes + trace.ops.size() * sizeof(TraceOp) + trace.boxes.size() * 6 * sizeof(float));
    put<uint32_t>(out, kTraceMagic);
    put<uint16_t>(out, kTraceVersion);
    put<uint16_t>(out, 0);
    put<uint32_t>(out, static_cast<uint32_t>(trace.ops.size()));
    put<uint32_t>(out, static_cast<uint32_t>(trace.boxes.size()));
    put<uint64_t>(out, trace.dropped);
    for (const TraceOp& op : trace.ops) put(out, op);
    for (const Bounds3f& box : trace.boxes)
        for (float v : {box.lower.x, box.lower.y, box.lower.z, box.upper.x, box.upper.y, box.upper.z}) put(out, v);
    return out;
}

TraversalTrace decodeTraversalTrace(std::span<const uint8_t> bytes, uint32_t maxOps) {
    check(bytes.size() >= kTraceHeaderBytes, "a trace is shorter than its header");
    check(get<uint32_t>(bytes, 0) == kTraceMagic, "not a traversal trace (wrong magic number)");
    check(get<uint16_t>(bytes, 4) == kTraceVersion, "a trace of an unknown version");
    check(get<uint16_t>(bytes, 6) == 0, "a trace header with a non-zero reserved field");
    uint32_t opCount = get<uint32_t>(bytes, 8), boxCount = get<uint32_t>(bytes, 12);
    check(opCount <= maxOps, "a trace of " + std::to_string(opCount) + " operations, more than the " + std::to_string(maxOps) + " allowed");
    check(boxCount <= opCount, "a trace with more boxes than operations");
    // Both counts are below 2^32, so the sum cannot overflow 64 bits.
    uint64_t expected = kTraceHeaderBytes + uint64_t(opCount) * sizeof(TraceOp) + uint64_t(boxCount) * 6 * sizeof(float);
    check(bytes.size() == expected, "a trace of " + std::to_string(bytes.size()) + " bytes where its header promises " +
                                        std::to_string(expected));
    TraversalTrace trace;
    trace.capacity = maxOps;
    trace.dropped = get<uint64_t>(bytes, 16);
    trace.ops.resize(opCount);
    size_t at = kTraceHeaderBytes;
    uint32_t boxTests = 0;
    for (uint32_t i = 0; i < opCount; ++i, at += sizeof(TraceOp)) {
        auto kind = get<uint8_t>(bytes, at);
        check(kind < kTraceOpKinds, "trace operation " + std::to_string(i) + " has an unknown kind");
        TraceOp op;
        op.kind = static_cast<TraceOpKind>(kind);
        op.hit = get<uint8_t>(bytes, at + 1);
        op.reserved = get<uint16_t>(bytes, at + 2);
        op.index = get<uint32_t>(bytes, at + 4);
        op.t = get<float>(bytes, at + 8);
        op.tFar = get<float>(bytes, at + 12);
        std::string where = "trace operation " + std::to_string(i);
        check(op.reserved == 0, where + " has a non-zero reserved field");
        bool mayHit = op.kind == TraceOpKind::BoxTest || op.kind == TraceOpKind::PrimitiveTest;
        check(op.hit == 0 || (op.hit == 1 && mayHit), where + " has a bad hit flag");
        if (op.kind == TraceOpKind::BoxTest) check(op.index == boxTests++, where + " names the wrong box");
        if (op.kind == TraceOpKind::CellStep || op.kind == TraceOpKind::PlaneStep)
            check(op.index == kTraceNoIndex, where + " has an index where none belongs");
        trace.ops[i] = op;
    }
    check(boxTests == boxCount, "a trace whose box tests and boxes disagree in number");
    trace.boxes.resize(boxCount);
    for (Bounds3f& box : trace.boxes) {
        float v[6];
        std::memcpy(v, bytes.data() + at, sizeof v);
        at += sizeof v;
        box.lower = Vec3(v[0], v[1], v[2]);
        box.upper = Vec3(v[3], v[4], v[5]);
    }
    return trace;
}

void writeTraversalTraceFile(const std::string& path, const TraversalTrace& trace) {
    std::vector<uint8_t> bytes = encodeTraversalTrace(trace);
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!file) throw TraceFormatError(path + ": cannot write the trace");
}

TraversalTrace readTraversalTraceFile(const std::string& path, uint32_t maxOps) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw TraceFormatError(path + ": cannot read the trace");
    // Never more than the largest valid trace plus one byte, whatever the file's size.
    uint64_t limit = kTraceHeaderBytes + uint64_t(maxOps) * (sizeof(TraceOp) + 6 * sizeof(float)) + 1;
    std::vector<uint8_t> bytes;
    char buffer[1 << 16];
    while (file && bytes.size() < limit) {
        file.read(buffer, sizeof buffer);
        bytes.insert(bytes.end(), buffer, buffer + file.gcount());
    }
    if (bytes.size() >= limit) throw TraceFormatError(path + ": larger than any trace of " + std::to_string(maxOps) + " operations");
    try {
        return decodeTraversalTrace(bytes, maxOps);
    } catch (const TraceFormatError& e) {
        throw TraceFormatError(path + ": " + e.what());
    }
}

}  // namespace rtlab
