#include "grader/engine/submission_toolchain.h"

#include "framework/core/error.h"

#include <filesystem>
#include <fstream>

namespace rtlab::grader {

nlohmann::json readToolchain(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": missing; build rtlab first (make build)");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(path + ": malformed (" + e.what() + ")");
    }
}

std::vector<std::string> compilerCommand(const nlohmann::json& toolchain) {
    std::vector<std::string> command = {std::filesystem::canonical(toolchain.at("compiler").get<std::string>()).string()};
    for (const auto& flag : toolchain.at("compile_flags")) command.push_back(flag.get<std::string>());
    return command;
}

}  // namespace rtlab::grader
