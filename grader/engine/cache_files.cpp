#include "grader/engine/cache_files.h"

#include "framework/core/sha256.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <vector>

namespace rtlab::grader {

namespace fs = std::filesystem;

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void ContentKey::add(const std::string& part) { text_ += std::to_string(part.size()) + ":" + part; }

void ContentKey::addFile(const std::string& name, const fs::path& file) {
    add(name);
    add(readBytes(file));
}

void ContentKey::addFolder(const fs::path& root) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) addFile(file.lexically_relative(root).string(), file);
}

std::string ContentKey::digest() const { return sha256Hex(text_); }

bool publishCopy(const fs::path& from, const fs::path& to) {
    std::error_code error;
    const fs::path temporary = to.string() + "." + std::to_string(getpid()) + ".tmp";
    fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, error);
    if (!error) fs::rename(temporary, to, error);
    if (error) fs::remove(temporary, error);
    return !error;
}

}  // namespace rtlab::grader
