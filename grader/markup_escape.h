// Escaping text (student output, messages) for the HTML and JUnit XML reports.
#pragma once

#include <string>

namespace rtlab::grader {

// Replaces & < > " by entities and drops control characters other than newline and tab, which
// XML 1.0 does not allow and which student output may contain.
inline std::string escapeMarkup(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default:
            if (static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t') out += c;
        }
    }
    return out;
}

}  // namespace rtlab::grader
