// The grader's reading of what a worker sends on its result pipe (worker/worker_protocol.h):
// records are parsed with bounds checks and must follow the conversation, phase by phase. The
// worker is hostile, so this is the parser that matters most: every byte it accepts or
// refuses is decided here, apart from pipes and processes (sandbox.cpp), so it can be fuzzed.
#pragma once

#include "grader/wire/worker_protocol.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rtlab::grader {

struct WorkerEvent {
    enum class Kind { Started, Verdict, Done } kind;
    size_t phase = 0;
    worker::RecordKind record = worker::RecordKind::Done;  // for verdicts: how the phase ended
    std::vector<uint8_t> payload;
    size_t droppedBytes = 0;  // of a text record's payload beyond kMaxTextPayload
};

class WorkerConversation {
public:
    // order: the phases the grader sends, in the order it sends them.
    explicit WorkerConversation(std::vector<size_t> order) : order_(std::move(order)) {}

    // Takes bytes from the result pipe and returns the events they complete, up to and
    // including the first verdict: bytes after it are kept until the grader has answered with
    // advance() and calls feed again (with no new bytes, to go on). Once a record is malformed
    // (unknown kind, too long, out of turn, for another phase), nothing more is accepted and
    // malformed() stays true.
    std::vector<WorkerEvent> feed(std::span<const uint8_t> bytes);

    // The grader moves on after a verdict (or when it gives up on the current phase).
    void advance() {
        ++step_;
        started_ = false;
        verdictGiven_ = false;
    }

    // The phase being run, or none once every phase of the order is through.
    std::optional<size_t> currentPhase() const { return step_ < order_.size() ? std::optional(order_[step_]) : std::nullopt; }
    size_t step() const { return step_; }
    bool started() const { return started_; }
    bool malformed() const { return malformed_; }
    bool done() const { return done_; }

    static constexpr uint64_t kMaxPayload = uint64_t(1) << 30;
    // A text record (NotStarted, Failed, NotRun: a name, an exception's message or why a phase
    // was not run) keeps at most this many bytes of its payload: the rest is read and dropped
    // here, so no report, table or CSV downstream ever holds more of what student code says
    // than this.
    static constexpr size_t kMaxTextPayload = 512;

private:
    std::optional<WorkerEvent> accept(uint8_t kind, uint32_t phase, std::span<const uint8_t> payload);

    std::vector<size_t> order_;
    size_t step_ = 0;
    bool started_ = false;
    bool verdictGiven_ = false;
    bool malformed_ = false;
    bool done_ = false;
    std::vector<uint8_t> pending_;
};

}  // namespace rtlab::grader
