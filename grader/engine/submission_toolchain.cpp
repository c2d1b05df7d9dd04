#include "grader/engine/submission_toolchain.h"

#include "grader/engine/json_file.h"

#include <filesystem>

namespace rtlab::grader {

nlohmann::json readToolchain(const std::string& path) {
    return readJsonFile(path, "toolchain", "missing; build rtlab first (make build)");
}

std::vector<std::string> compilerCommand(const nlohmann::json& toolchain) {
    std::vector<std::string> command = {std::filesystem::canonical(toolchain.at("compiler").get<std::string>()).string()};
    for (const auto& flag : toolchain.at("compile_flags")) command.push_back(flag.get<std::string>());
    return command;
}

}  // namespace rtlab::grader
