// Reading a JSON file the grader depends on: the submission toolchain, a rubric, a saved report.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace rtlab::grader {

// The parsed file. A file that cannot be opened throws rtlab::Error "PATH: whenMissing"; one that
// does not parse throws "PATH: malformed WHAT (the parser's words)". Either is one line.
nlohmann::json readJsonFile(const std::string& path, const std::string& what, const std::string& whenMissing);

}  // namespace rtlab::grader
