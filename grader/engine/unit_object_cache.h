// Objects of single submission files, kept by the SHA-256 of everything their compile could
// read (docs/grading.md, "Grading a submission"). Most of a submission is the same bytes from
// one grading to the next: the files a student has not touched since the last `make grade`,
// the stubs of a graded folder, or the reference files a test lays a mutant over. Each of those
// compiles once; later gradings copy its object and the compiler's messages.
//
// The key is computed by the grader from files it wrote itself, never from anything the
// compiler reports, so a compile cannot file an object under another input's key. It holds
// only what the compile can see: each file compiles in a view holding the submission's headers
// and that one .cpp (worker_compile.h), so no other .cpp reaches it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace rtlab::grader {

// Above this many bytes of objects the least recently used are removed when one is added.
inline constexpr std::uintmax_t kUnitObjectCacheBytes = std::uintmax_t(256) << 20;

class UnitObjectCache {
public:
    // dir: where objects are kept, created when first needed; empty: nothing is kept.
    // compiler: the compiler's canonical path; with its size and time, part of every key.
    // sharedDigest: a digest of every byte the units share (the flags, the student headers, the
    // submission's own headers, each with its path), made by the caller from files it wrote.
    UnitObjectCache(std::filesystem::path dir, const std::filesystem::path& compiler, const std::string& sharedDigest);

    // The key of one .cpp of the submission, by its path under the sources and its bytes.
    std::string key(const std::string& path, const std::string& contents) const;

    // Copies the object of `key` to `object` and returns true with the compiler's messages
    // in *log; false when there is none (or it vanished under a concurrent trim).
    bool fetch(const std::string& key, const std::filesystem::path& object, std::string* log) const;

    // Keeps a compiled object and its messages under `key`; failures to keep it are ignored
    // (the grading has its object either way).
    void store(const std::string& key, const std::filesystem::path& object, const std::string& log) const;

    bool enabled() const { return !dir_.empty(); }

private:
    void trim() const;

    std::filesystem::path dir_;
    std::string inputsDigest_;
};

}  // namespace rtlab::grader
