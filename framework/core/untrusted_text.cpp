#include "framework/core/untrusted_text.h"

#include <cstdint>
#include <cstdio>

namespace rtlab::grader {
namespace {

// Length of the well-formed UTF-8 sequence at bytes[i] (Unicode 15, table 3-7) and its code
// point, or 0 when the bytes there are not one.
size_t decodeUtf8(std::string_view bytes, size_t i, uint32_t& codePoint) {
    auto at = [&](size_t k) { return static_cast<unsigned char>(bytes[k]); };
    unsigned char lead = at(i);
    if (lead < 0x80) {
        codePoint = lead;
        return 1;
    }
    size_t length;
    unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
        codePoint = lead & 0x1F;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        codePoint = lead & 0x0F;
        if (lead == 0xE0) low = 0xA0;   // overlong
        if (lead == 0xED) high = 0x9F;  // surrogates
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        codePoint = lead & 0x07;
        if (lead == 0xF0) low = 0x90;   // overlong
        if (lead == 0xF4) high = 0x8F;  // above U+10FFFF
    } else {
        return 0;
    }
    if (i + length > bytes.size()) return 0;
    for (size_t k = 1; k < length; ++k) {
        unsigned char c = at(i + k);
        if (c < (k == 1 ? low : 0x80) || c > (k == 1 ? high : 0xBF)) return 0;
        codePoint = (codePoint << 6) | (c & 0x3F);
    }
    return length;
}

bool isDisplayedAsEscape(uint32_t c, TextLayout layout) {
    if (c == '\n' || c == '\t') return layout == TextLayout::OneLine;
    if (c < 0x20 || c == 0x7F) return true;
    if (c >= 0x80 && c <= 0x9F) return true;
    if (c == 0xFFFE || c == 0xFFFF) return true;
    return (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069);
}

void appendEscape(std::string& out, uint32_t value, bool isByte) {
    char buffer[16];
    if (isByte)
        std::snprintf(buffer, sizeof buffer, "\\x%02x", static_cast<unsigned>(value));
    else
        std::snprintf(buffer, sizeof buffer, "\\u{%04X}", static_cast<unsigned>(value));
    out += buffer;
}

}  // namespace

std::string escapeUntrusted(std::string_view bytes, TextLayout layout) {
    std::string out;
    out.reserve(bytes.size());
    for (size_t i = 0; i < bytes.size();) {
        uint32_t codePoint = 0;
        size_t length = decodeUtf8(bytes, i, codePoint);
        if (length == 0) {
            appendEscape(out, static_cast<unsigned char>(bytes[i]), true);
            ++i;
            continue;
        }
        if (isDisplayedAsEscape(codePoint, layout))
            appendEscape(out, codePoint, codePoint < 0x80);
        else
            out.append(bytes.substr(i, length));
        i += length;
    }
    return out;
}

std::string truncateUtf8(const std::string& text, size_t maxBytes) {
    if (text.size() <= maxBytes) return text;
    size_t end = maxBytes;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
    return text.substr(0, end);
}

}  // namespace rtlab::grader
