// Running the `povray` executable headless, from a working folder it may write in (Debian's
// povray.conf lets POV-Ray write only in its current directory and the system temp folder).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

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

// Runs `povray arguments...` in workDir with stdin from /dev/null and stdout + stderr into
// logPath; returns POV-Ray's exit status. Throws rtlab::Error when povray cannot be started.
int runPovray(const std::vector<std::string>& arguments, const std::filesystem::path& workDir,
              const std::filesystem::path& logPath);

// Runs povray in `work` with its log in work/povray.log. When it exits non-zero, keeps the
// folder and throws rtlab::Error with one line: `what` was being done, POV-Ray's first error
// line and the log path.
void runPovrayOrThrow(const std::vector<std::string>& arguments, TemporaryDirectory& work,
                      const std::string& what);

// The version line `povray --version` prints, e.g. "POV-Ray 3.7.0.10.unofficial".
std::string povrayVersion();

}  // namespace rtlab
