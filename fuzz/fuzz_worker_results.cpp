// libFuzzer target: what the grader reads from a worker, which is hostile: the record stream of
// its result pipe (WorkerConversation, grader/engine/worker_conversation.h) and the payloads of its
// verdicts decoded with ByteReader into the result types the grader scores: a BVH, which
// the grader then checks itself (checkBvhStructure, graderSahCost), and per-ray answers.
//
// Input: byte 0 sets the phases of the request (1 + byte % 8), byte 1 the size of the chunks
// (1 + byte) in which the rest, the pipe's bytes, arrives.
#include "framework/core/bounds.h"
#include "grader/a1_bvh/bvh_structure.h"
#include "grader/wire/wire_format.h"
#include "grader/wire/task_inputs.h"
#include "grader/engine/worker_conversation.h"

#include <cstdlib>
#include <numeric>

namespace {

using namespace rtlab;
using namespace rtlab::grader;

// Eight unit boxes in a row: the primitives of the BVH a build phase reports.
const std::vector<Bounds3f>& primitiveBounds() {
    static const std::vector<Bounds3f> bounds = [] {
        std::vector<Bounds3f> b;
        for (int i = 0; i < 8; ++i) b.emplace_back(Vec3(float(i), 0.0f, 0.0f), Vec3(float(i) + 1.0f, 1.0f, 1.0f));
        return b;
    }();
    return bounds;
}

// As the BVH tests read a build's results (grader/a1_bvh/bvh_tests.cpp): bounded lists, then the
// grader's own checks of the structure, which must hold against any bytes.
void decodeBvh(ByteReader& in) {
    size_t primCount = primitiveBounds().size();
    Bvh bvh;
    bvh.nodes = in.getVector<BvhNode>(4 * primCount + 16);
    bvh.primIndices = in.getVector<uint32_t>(4 * primCount + 16);
    BvhStructureReport report = checkBvhStructure(bvh, primitiveBounds(), true);
    if (report.problemCount == 0 && !(graderSahCost(bvh) >= 0.0)) std::abort();
    if (report.problemCount < report.problems.size()) std::abort();
}

// As the query tests read answers: one RawQuery per ray, and nothing after them.
void decodeAnswers(ByteReader& in) {
    constexpr size_t kRays = 16;
    auto answers = in.getVector<worker::RawQuery>(kRays);
    if (answers.size() > kRays) std::abort();
    std::string note = in.getString(256);
    if (note.size() > 256) std::abort();
}

void decodeVerdict(const WorkerEvent& event) {
    ByteReader in(event.payload);
    try {
        if (event.record == worker::RecordKind::Forbidden) in.get<int32_t>();
        else if (event.record == worker::RecordKind::PhaseData && event.phase % 2 == 0) decodeBvh(in);
        else if (event.record == worker::RecordKind::PhaseData) decodeAnswers(in);
    } catch (const WireError&) {
        // A malformed payload: the test fails with the reason; nothing is trusted.
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 2) return 0;
    std::vector<size_t> order(1 + data[0] % 8);
    std::iota(order.begin(), order.end(), size_t{0});
    size_t chunk = 1 + size_t{data[1]};
    std::span<const uint8_t> pipe(data + 2, size - 2);

    WorkerConversation conversation(order);
    size_t offset = 0;
    bool answered = false;  // a verdict was answered: feed again, with or without new bytes
    while (offset < pipe.size() || answered) {
        size_t n = std::min(chunk, pipe.size() - offset);
        bool wasMalformed = conversation.malformed();
        std::vector<WorkerEvent> events = conversation.feed(pipe.subspan(offset, n));
        offset += n;
        if (wasMalformed && !events.empty()) std::abort();  // malformed is for good
        answered = false;
        for (const WorkerEvent& event : events) {
            if (event.payload.size() > WorkerConversation::kMaxPayload) std::abort();
            if (event.kind == WorkerEvent::Kind::Done) continue;
            if (conversation.currentPhase() != event.phase) std::abort();  // only the phase being run
            if (event.kind == WorkerEvent::Kind::Verdict) {
                decodeVerdict(event);
                conversation.advance();
                answered = true;
            }
        }
    }
    return 0;
}
