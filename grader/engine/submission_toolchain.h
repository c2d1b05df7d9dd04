// The toolchain submissions are built with: build/grader/submission-toolchain.json, which
// grader/CMakeLists.txt writes from the build's own compiler and flags, so that a submission
// compiles as the committed code does.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rtlab::grader {

// The file's contents. Throws rtlab::Error with one line when it is missing or malformed.
nlohmann::json readToolchain(const std::string& path);

// The compiler by its canonical path, then the compile flags: the start of every compile of a
// submission, of the committed stubs and of the precompiled student headers.
std::vector<std::string> compilerCommand(const nlohmann::json& toolchain);

}  // namespace rtlab::grader
