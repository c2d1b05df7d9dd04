// Escaping text (student output, messages) for the HTML and JUnit XML reports.
#pragma once

#include "framework/core/untrusted_text.h"

#include <string>

namespace rtlab::grader {

// escapeUntrusted (so no byte XML 1.0 forbids and no invalid UTF-8 remains; newline and tab
// kept), then & < > " ' as entities.
inline std::string escapeMarkup(const std::string& text) {
    std::string safe = escapeUntrusted(text, TextLayout::Lines), out;
    out.reserve(safe.size());
    for (char c : safe) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

}  // namespace rtlab::grader
