// Text from outside the grader (what student code prints, compiler messages, folder names,
// reasons built from them) made safe for every report (docs/grading.md, "Reports"): the
// terminal must not obey escape sequences, JSON must be valid UTF-8, XML 1.0 forbids most
// control characters. Every report writer passes its text through escapeUntrusted.
#pragma once

#include <string>
#include <string_view>

namespace rtlab::grader {

enum class TextLayout {
    Lines,     // newline and tab kept (pre blocks, JSON strings, details)
    OneLine,   // newline and tab escaped too (table cells, attribute values, CSV fields)
};

// Valid UTF-8 passes through. Everything else becomes a visible, pure-ASCII escape:
//   - a byte that is not part of valid UTF-8 (Latin-1, a character cut at a capture limit,
//     overlong forms, encoded surrogates): \xNN for each such byte;
//   - C0 controls and DEL (NUL, ESC, CR, BEL, ...): \xNN, except \n and \t in TextLayout::Lines;
//   - C1 controls U+0080..U+009F (CSI among them), the noncharacters U+FFFE and U+FFFF and the
//     bidirectional overrides U+202A..U+202E, U+2066..U+2069: \u{XXXX}.
// A backslash is left alone, so escaping is idempotent: text escaped by a grading child and
// read back is not escaped twice.
std::string escapeUntrusted(std::string_view bytes, TextLayout layout = TextLayout::Lines);

// At most maxBytes bytes of valid UTF-8 text, never cutting a character in two.
std::string truncateUtf8(const std::string& text, size_t maxBytes);

}  // namespace rtlab::grader
