// What the grader still has to write to a worker's input pipe: the framing of each request,
// which the queue owns, and the phases' inputs, which it only views (they outlive the run).
// Copying an input into one buffer first cost a page fault per 4 KiB of megabytes of
// triangles and rays, and erasing what was written from the front moved the rest each time.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <deque>
#include <span>
#include <unistd.h>
#include <vector>

namespace rtlab::grader {

class RequestQueue {
public:
    template <typename T>
    void put(T value) {
        const auto* p = reinterpret_cast<const uint8_t*>(&value);
        own({p, sizeof value});
    }
    void own(std::span<const uint8_t> bytes) {
        if (segments_.empty() || !segments_.back().owned) segments_.push_back({{}, {}, true});
        segments_.back().bytes.insert(segments_.back().bytes.end(), bytes.begin(), bytes.end());
    }
    void view(std::span<const uint8_t> bytes) {
        if (!bytes.empty()) segments_.push_back({{}, bytes, false});
    }
    bool empty() const { return segments_.empty(); }

    // Writes what the pipe takes now. False when the worker has closed its input: what is
    // left is dropped.
    bool writeTo(int fd) {
        std::span<const uint8_t> front = segments_.front().data();
        ssize_t n = write(fd, front.data() + sent_, front.size() - sent_);
        if (n < 0 && errno != EAGAIN && errno != EINTR) {
            segments_.clear();
            sent_ = 0;
            return false;
        }
        if (n > 0) sent_ += size_t(n);
        if (sent_ == front.size()) {
            segments_.pop_front();
            sent_ = 0;
        }
        return true;
    }

private:
    struct Segment {
        std::vector<uint8_t> bytes;      // when owned
        std::span<const uint8_t> viewed;  // when not
        bool owned;
        std::span<const uint8_t> data() const { return owned ? std::span<const uint8_t>(bytes) : viewed; }
    };
    std::deque<Segment> segments_;
    size_t sent_ = 0;  // bytes of the front segment already written
};

}  // namespace rtlab::grader
