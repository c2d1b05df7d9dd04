// A submission's folder, read without following a symbolic link at any component of any path
// (docs/grading.md, "Isolation and trust"). A link anywhere below the submission's root (the
// file itself, its folder, assignments/) could point at what the grader may read and the
// student may not: solutions/, reference data, another student's submission in a batch. So
// each path is opened one component at a time with O_NOFOLLOW from the root down, and a link
// met on the way is refused with an error naming it. The root itself is the instructor's
// choice and may be reached through links.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rtlab::grader {

class SubmissionFolder {
public:
    // Throws rtlab::Error when root is not a folder.
    explicit SubmissionFolder(const std::filesystem::path& root);
    ~SubmissionFolder();
    SubmissionFolder(const SubmissionFolder&) = delete;
    SubmissionFolder& operator=(const SubmissionFolder&) = delete;

    enum class Kind { Missing, File, Folder, Other };
    // What `relative` names; throws rtlab::Error naming the component that is a symbolic link.
    Kind kind(const std::filesystem::path& relative) const;
    // A regular file of at most maxBytes; throws rtlab::Error naming it otherwise.
    std::string read(const std::filesystem::path& relative, size_t maxBytes) const;
    // The names in a folder (no "." or ".."), sorted; throws like kind().
    std::vector<std::string> list(const std::filesystem::path& relative) const;

    const std::filesystem::path& root() const { return root_; }

private:
    // An open descriptor of relative's last component (O_PATH-free: a real open), every
    // component before it a folder that is no link; -1 with errno ENOENT when missing.
    int open(const std::filesystem::path& relative, int flags) const;

    std::filesystem::path root_;
    int rootFd_ = -1;
};

}  // namespace rtlab::grader
