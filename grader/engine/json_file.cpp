#include "grader/engine/json_file.h"

#include "framework/core/error.h"

#include <fstream>

namespace rtlab::grader {

nlohmann::json readJsonFile(const std::string& path, const std::string& what, const std::string& whenMissing) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": " + whenMissing);
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(path + ": malformed " + what + " (" + e.what() + ")");
    }
}

}  // namespace rtlab::grader
