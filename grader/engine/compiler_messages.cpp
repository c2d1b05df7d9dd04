#include "grader/engine/compiler_messages.h"

#include <sstream>

namespace rtlab::grader {

std::vector<std::string> splitLines(const std::string& text, size_t maxLines) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line) && lines.size() < maxLines;) lines.push_back(line);
    return lines;
}

std::string firstError(const std::string& log) {
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);)
        if (line.find("error") != std::string::npos) return line;
    auto lines = splitLines(log, 1);
    return lines.empty() ? "no output" : lines.front();
}

}  // namespace rtlab::grader
