// What the grader's object caches share (stub_object_cache.h, unit_object_cache.h): the text a
// key is the SHA-256 of, and how an entry is written so that a reader never sees half of it.
#pragma once

#include <filesystem>
#include <string>

namespace rtlab::grader {

// Parts appended length-prefixed, so that no two different inputs run together into one text.
class ContentKey {
public:
    void add(const std::string& part);
    // A file by its path (as the key should name it) and its bytes.
    void addFile(const std::string& name, const std::filesystem::path& file);
    // Every regular file under root, in path order, named relative to root.
    void addFolder(const std::filesystem::path& root);

    std::string digest() const;  // hex SHA-256 of everything added

private:
    std::string text_;
};

// A file's bytes; empty when it cannot be read.
std::string readBytes(const std::filesystem::path& file);

// Copies from to a name of this process beside to, then renames it: another grader filling the
// same entry at the same time leaves one whole copy, and either is right. False when it failed.
bool publishCopy(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace rtlab::grader
