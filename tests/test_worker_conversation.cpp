// The grader's parser of what a worker sends (grader/engine/worker_conversation.h): a well-behaved
// worker's records give one start and one verdict per phase, however the bytes are split;
// every record out of turn is malformed, and stays so.
#include "grader/engine/worker_conversation.h"

#include <doctest/doctest.h>

#include <cstring>

using namespace rtlab::grader;
using rtlab::grader::worker::RecordKind;

namespace {

void append(std::vector<uint8_t>& bytes, RecordKind kind, uint32_t phase, const std::vector<uint8_t>& payload = {}) {
    uint8_t header[worker::kRecordHeaderSize];
    header[0] = static_cast<uint8_t>(kind);
    uint64_t size = payload.size();
    std::memcpy(header + 1, &phase, 4);
    std::memcpy(header + 5, &size, 8);
    bytes.insert(bytes.end(), header, header + sizeof header);
    bytes.insert(bytes.end(), payload.begin(), payload.end());
}

// Feeds the bytes `chunk` at a time and answers every verdict as the grader does.
std::vector<WorkerEvent> converse(WorkerConversation& c, const std::vector<uint8_t>& bytes, size_t chunk) {
    std::vector<WorkerEvent> all;
    for (size_t at = 0; at < bytes.size(); at += chunk) {
        auto events = c.feed(std::span(bytes).subspan(at, std::min(chunk, bytes.size() - at)));
        while (!events.empty()) {
            for (WorkerEvent& e : events) {
                if (e.kind == WorkerEvent::Kind::Verdict) c.advance();
                all.push_back(std::move(e));
            }
            events = c.feed({});
        }
    }
    return all;
}

}  // namespace

TEST_CASE("worker conversation: a well-behaved worker, in any chunking") {
    std::vector<uint8_t> bytes;
    append(bytes, RecordKind::PhaseStart, 0);
    append(bytes, RecordKind::PhaseData, 0, {1, 2, 3});
    append(bytes, RecordKind::PhaseStart, 2);
    append(bytes, RecordKind::NotStarted, 2, {'x'});
    append(bytes, RecordKind::Done, 0);
    for (size_t chunk : {size_t(1), size_t(5), bytes.size()}) {
        CAPTURE(chunk);
        WorkerConversation c({0, 2});
        auto events = converse(c, bytes, chunk);
        REQUIRE(events.size() == 5);
        CHECK(events[1].payload == std::vector<uint8_t>{1, 2, 3});
        CHECK(events[3].phase == 2);
        CHECK(events[3].record == RecordKind::NotStarted);
        CHECK(c.done());
        CHECK_FALSE(c.malformed());
    }
}

TEST_CASE("worker conversation: records out of turn are malformed") {
    auto verdictOf = [](std::vector<uint8_t> bytes) {
        WorkerConversation c({0, 1});
        converse(c, bytes, bytes.size());
        return c.malformed();
    };
    std::vector<uint8_t> twoStarts, otherPhase, dataBeforeStart, earlyDone, secondVerdict, unknownKind, hugePayload, afterDone;
    append(twoStarts, RecordKind::PhaseStart, 0);
    append(twoStarts, RecordKind::PhaseStart, 0);
    CHECK(verdictOf(twoStarts));
    append(otherPhase, RecordKind::PhaseStart, 1);
    CHECK(verdictOf(otherPhase));
    append(dataBeforeStart, RecordKind::PhaseData, 0);
    CHECK(verdictOf(dataBeforeStart));
    append(earlyDone, RecordKind::Done, 0);
    CHECK(verdictOf(earlyDone));
    append(secondVerdict, RecordKind::PhaseStart, 0);
    append(secondVerdict, RecordKind::PhaseData, 0);
    append(secondVerdict, RecordKind::PhaseData, 0);
    CHECK(verdictOf(secondVerdict));
    unknownKind.assign(worker::kRecordHeaderSize, 0);
    unknownKind[0] = 99;
    CHECK(verdictOf(unknownKind));
    append(hugePayload, RecordKind::PhaseStart, 0);
    hugePayload.push_back(uint8_t(RecordKind::PhaseData));
    for (int i = 0; i < 4; ++i) hugePayload.push_back(0);
    for (int i = 0; i < 8; ++i) hugePayload.push_back(0xff);
    CHECK(verdictOf(hugePayload));
    for (size_t phase : {0u, 1u}) {
        append(afterDone, RecordKind::PhaseStart, uint32_t(phase));
        append(afterDone, RecordKind::PhaseData, uint32_t(phase));
    }
    append(afterDone, RecordKind::Done, 0);
    CHECK_FALSE(verdictOf(afterDone));
    append(afterDone, RecordKind::Done, 0);
    CHECK(verdictOf(afterDone));
}

TEST_CASE("worker conversation: a forbidden call may come before the phase starts") {
    std::vector<uint8_t> bytes;
    append(bytes, RecordKind::Forbidden, 0, {2, 1, 0, 0});
    WorkerConversation c({0});
    auto events = c.feed(bytes);
    REQUIRE(events.size() == 1);
    CHECK(events[0].record == RecordKind::Forbidden);
    CHECK_FALSE(c.malformed());
}

TEST_CASE("worker conversation: a phase not run is a verdict, its reason cut like any text") {
    std::vector<uint8_t> bytes;
    append(bytes, RecordKind::PhaseStart, 0);
    append(bytes, RecordKind::NotRun, 0, std::vector<uint8_t>(WorkerConversation::kMaxTextPayload + 100, 'n'));
    append(bytes, RecordKind::Done, 0);
    WorkerConversation c({0});
    auto events = converse(c, bytes, bytes.size());
    REQUIRE(events.size() == 3);
    CHECK(events[1].kind == WorkerEvent::Kind::Verdict);
    CHECK(events[1].record == RecordKind::NotRun);
    CHECK(events[1].payload.size() == WorkerConversation::kMaxTextPayload);
    CHECK(events[1].droppedBytes == 100);
    CHECK(c.done());
    CHECK_FALSE(c.malformed());
}
