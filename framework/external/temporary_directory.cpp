#include "framework/external/temporary_directory.h"

#include "framework/core/error.h"

#include <stdlib.h>

#include <cerrno>
#include <cstring>

namespace rtlab {
namespace fs = std::filesystem;

TemporaryDirectory::TemporaryDirectory(const std::string& prefix) {
    std::string pattern = (fs::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
        throw Error("cannot create a temporary folder " + pattern + ": " + std::strerror(errno));
    path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
    if (keep_) return;
    std::error_code ignored;  // a destructor must not throw; a leftover temp folder is harmless
    fs::remove_all(path_, ignored);
}

}  // namespace rtlab
