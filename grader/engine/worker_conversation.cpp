#include "grader/engine/worker_conversation.h"

#include <cstring>

namespace rtlab::grader {

using worker::RecordKind;

std::vector<WorkerEvent> WorkerConversation::feed(std::span<const uint8_t> bytes) {
    std::vector<WorkerEvent> events;
    if (malformed_ || done_) {
        malformed_ = malformed_ || !bytes.empty() || !pending_.empty();  // nothing may follow Done
        return events;
    }
    pending_.insert(pending_.end(), bytes.begin(), bytes.end());
    size_t position = 0;
    while (pending_.size() - position >= worker::kRecordHeaderSize && !malformed_ && !done_) {
        const uint8_t* header = pending_.data() + position;
        uint32_t phase;
        uint64_t size;
        std::memcpy(&phase, header + 1, 4);
        std::memcpy(&size, header + 5, 8);
        if (header[0] < worker::kFirstRecordKind || header[0] > worker::kLastRecordKind || size > kMaxPayload) {
            malformed_ = true;
            break;
        }
        if (pending_.size() - position - worker::kRecordHeaderSize < size) break;
        auto event = accept(header[0], phase, std::span(header + worker::kRecordHeaderSize, size));
        position += worker::kRecordHeaderSize + size;
        if (!event) continue;
        bool verdict = event->kind == WorkerEvent::Kind::Verdict;
        events.push_back(std::move(*event));
        if (verdict) break;  // the rest waits for advance()
    }
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(position));
    if (done_ && !pending_.empty()) malformed_ = true;
    return events;
}

// Each phase starts once and ends with one verdict, which the grader answers with advance();
// Done comes only after the last phase. A forbidden-call report may come before the start:
// it is raised by start-up code, or by the worker's own reading of the request.
std::optional<WorkerEvent> WorkerConversation::accept(uint8_t kind, uint32_t phase, std::span<const uint8_t> payload) {
    auto record = static_cast<RecordKind>(kind);
    auto current = currentPhase();
    if (record == RecordKind::Done) {
        if (current || !payload.empty()) malformed_ = true;
        else done_ = true;
        return done_ ? std::optional(WorkerEvent{WorkerEvent::Kind::Done, 0, record, {}}) : std::nullopt;
    }
    if (!current || phase != *current || verdictGiven_) {
        malformed_ = true;
        return std::nullopt;
    }
    if (record == RecordKind::PhaseStart) {
        if (started_ || !payload.empty()) {
            malformed_ = true;
            return std::nullopt;
        }
        started_ = true;
        return WorkerEvent{WorkerEvent::Kind::Started, phase, record, {}};
    }
    if (!started_ && record != RecordKind::Forbidden) {
        malformed_ = true;
        return std::nullopt;
    }
    verdictGiven_ = true;
    size_t dropped = 0;
    if ((record == RecordKind::NotStarted || record == RecordKind::Failed || record == RecordKind::NotRun) && payload.size() > kMaxTextPayload) {
        dropped = payload.size() - kMaxTextPayload;
        payload = payload.first(kMaxTextPayload);
    }
    return WorkerEvent{WorkerEvent::Kind::Verdict, phase, record, std::vector<uint8_t>(payload.begin(), payload.end()), dropped};
}

}  // namespace rtlab::grader
