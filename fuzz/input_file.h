// The parsers under fuzzing read files, so each input is written to a file of this process
// before the parser opens it: under /dev/shm where there is one (a disk-backed /tmp makes a
// run several times slower), else $TMPDIR or /tmp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace rtlab::fuzz {

// A private directory for this process's input files, removed at exit.
inline const std::filesystem::path& scratchDirectory() {
    static const std::filesystem::path directory = [] {
        const char* tmpdir = std::getenv("TMPDIR");
        std::filesystem::path base = std::filesystem::is_directory("/dev/shm") ? "/dev/shm"
                                     : tmpdir && *tmpdir                       ? tmpdir
                                                                               : "/tmp";
        std::filesystem::path path = base / ("rtlab-fuzz-" + std::to_string(getpid()));
        std::filesystem::create_directories(path);
        std::atexit([] { std::error_code ignored; std::filesystem::remove_all(scratchDirectory(), ignored); });
        return path;
    }();
    return directory;
}

// Writes bytes to scratchDirectory()/name and returns the path; aborts if it cannot (that is a
// broken machine, not a finding).
inline std::string writeInputFile(const std::string& name, const uint8_t* data, size_t size) {
    std::string path = (scratchDirectory() / name).string();
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) {
        std::perror(path.c_str());
        std::abort();
    }
    return path;
}

}  // namespace rtlab::fuzz
