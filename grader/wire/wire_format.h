// The byte format of raw results sent by a sandboxed child to the grader (docs/grading.md,
// "Trust"). The child only ever writes plain values; the parent reads them with bounds checks,
// so a child that sends garbage produces a WireError, never a crash or a trusted score.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rtlab::grader {

struct WireError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class ByteWriter {
public:
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const uint8_t*>(&value);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    template <typename T>
    void putVector(std::span<const T> values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put<uint64_t>(values.size());
        const auto* p = reinterpret_cast<const uint8_t*>(values.data());
        bytes_.insert(bytes_.end(), p, p + values.size_bytes());
    }
    template <typename T>
    void putVector(const std::vector<T>& values) {
        putVector(std::span<const T>(values));
    }
    void putString(const std::string& s) { putVector(std::span<const char>(s.data(), s.size())); }

    const std::vector<uint8_t>& bytes() const { return bytes_; }
    std::vector<uint8_t>& bytes() { return bytes_; }

private:
    std::vector<uint8_t> bytes_;
};

class ByteReader {
public:
    explicit ByteReader(std::span<const uint8_t> bytes) : bytes_(bytes) {}

    template <typename T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + position_, sizeof(T));
        position_ += sizeof(T);
        return value;
    }
    // maxCount guards against a forged length that would make the parent allocate gigabytes.
    template <typename T>
    std::vector<T> getVector(uint64_t maxCount) {
        auto count = get<uint64_t>();
        if (count > maxCount) throw WireError("a result list is longer than the test allows");
        need(count * sizeof(T));
        std::vector<T> values(count);
        if (count > 0) std::memcpy(values.data(), bytes_.data() + position_, count * sizeof(T));
        position_ += count * sizeof(T);
        return values;
    }
    std::string getString(uint64_t maxLength = 1 << 16) {
        auto chars = getVector<char>(maxLength);
        return std::string(chars.begin(), chars.end());
    }
    bool atEnd() const { return position_ == bytes_.size(); }

private:
    void need(uint64_t n) const {
        if (n > bytes_.size() - position_) throw WireError("the results end too early");
    }
    std::span<const uint8_t> bytes_;
    size_t position_ = 0;
};

}  // namespace rtlab::grader
