// A compiler's output read for a report: its lines, and the one that says what went wrong.
#pragma once

#include <string>
#include <vector>

namespace rtlab::grader {

// The first maxLines lines of text.
std::vector<std::string> splitLines(const std::string& text, size_t maxLines);

// The first line that says what went wrong: a compiler's "error" line when there is one, else
// the first line, else "no output".
std::string firstError(const std::string& log);

}  // namespace rtlab::grader
