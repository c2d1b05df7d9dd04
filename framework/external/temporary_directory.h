// A scratch folder for an external program (POV-Ray writes only in its current directory and
// the system temp folder), removed with everything in it unless a failed run's log is kept.
#pragma once

#include <filesystem>
#include <string>

namespace rtlab {

// A fresh folder under the system temp directory, removed with everything in it on
// destruction unless keep() was called (to leave a failed run's log for the user).
class TemporaryDirectory {
public:
    explicit TemporaryDirectory(const std::string& prefix);
    ~TemporaryDirectory();
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

    const std::filesystem::path& path() const { return path_; }
    void keep() { keep_ = true; }

private:
    std::filesystem::path path_;
    bool keep_ = false;
};

}  // namespace rtlab
