#include "grader/engine/submission_files.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rtlab::grader {

namespace fs = std::filesystem;

namespace {

// Closes a descriptor when it goes out of scope.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

SubmissionFolder::SubmissionFolder(const fs::path& root) : root_(root) {
    rootFd_ = ::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (rootFd_ < 0) throw Error(root.string() + ": the submission folder does not exist or cannot be opened");
}

SubmissionFolder::~SubmissionFolder() {
    if (rootFd_ >= 0) ::close(rootFd_);
}

int SubmissionFolder::open(const fs::path& relative, int flags) const {
    std::vector<std::string> parts;
    for (const fs::path& part : relative.lexically_normal())
        if (!part.empty() && part != ".") parts.push_back(part.string());
    if (std::find(parts.begin(), parts.end(), "..") != parts.end() || relative.is_absolute())
        throw Error((root_ / relative).string() + ": outside the submission");
    if (parts.empty()) return ::fcntl(rootFd_, F_DUPFD_CLOEXEC, 0);
    Descriptor folder{::fcntl(rootFd_, F_DUPFD_CLOEXEC, 0)};
    fs::path walked;
    for (size_t i = 0; i < parts.size(); ++i) {
        walked /= parts[i];
        bool last = i + 1 == parts.size();
        int fd = ::openat(folder.fd, parts[i].c_str(), (last ? flags : O_RDONLY | O_DIRECTORY) | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0) {
            int error = errno;
            struct stat entry{};
            if (::fstatat(folder.fd, parts[i].c_str(), &entry, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(entry.st_mode))
                throw Error((root_ / walked).string() + ": a symbolic link; submit the files themselves");
            if (error == ENOENT || error == ENOTDIR) {
                errno = ENOENT;
                return -1;
            }
            throw Error((root_ / walked).string() + ": cannot be opened (" + std::strerror(error) + ")");
        }
        if (last) return fd;
        ::close(folder.fd);
        folder.fd = fd;
    }
    return -1;
}

SubmissionFolder::Kind SubmissionFolder::kind(const fs::path& relative) const {
    Descriptor entry{open(relative, O_RDONLY)};
    if (entry.fd < 0) return Kind::Missing;
    struct stat status{};
    if (::fstat(entry.fd, &status) != 0) return Kind::Other;
    if (S_ISREG(status.st_mode)) return Kind::File;
    if (S_ISDIR(status.st_mode)) return Kind::Folder;
    return Kind::Other;
}

std::string SubmissionFolder::read(const fs::path& relative, size_t maxBytes) const {
    const std::string name = (root_ / relative).string();
    Descriptor file{open(relative, O_RDONLY)};
    if (file.fd < 0) throw Error(name + ": missing");
    struct stat status{};
    if (::fstat(file.fd, &status) != 0 || !S_ISREG(status.st_mode)) throw Error(name + ": not a regular file");
    if (uintmax_t(status.st_size) > maxBytes) throw Error(name + ": larger than " + std::to_string(maxBytes >> 20) + " MiB");
    std::string contents(size_t(status.st_size), '\0');
    size_t done = 0;
    while (done < contents.size()) {
        ssize_t n = ::read(file.fd, contents.data() + done, contents.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw Error(name + ": cannot be read");
        done += size_t(n);
    }
    return contents;
}

std::vector<std::string> SubmissionFolder::list(const fs::path& relative) const {
    Descriptor folder{open(relative, O_RDONLY | O_DIRECTORY)};
    if (folder.fd < 0) throw Error((root_ / relative).string() + ": missing");
    DIR* dir = ::fdopendir(folder.fd);
    if (!dir) throw Error((root_ / relative).string() + ": not a folder");
    folder.fd = -1;  // the DIR owns it now
    std::vector<std::string> names;
    while (const dirent* entry = ::readdir(dir)) {
        std::string name = entry->d_name;
        if (name != "." && name != "..") names.push_back(name);
    }
    ::closedir(dir);
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace rtlab::grader
