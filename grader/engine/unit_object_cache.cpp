#include "grader/engine/unit_object_cache.h"

#include "grader/engine/cache_files.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <vector>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// The compiler as installed: an upgrade of the package changes its size or time.
std::string compilerIdentity(const fs::path& compiler) {
    std::error_code error;
    auto size = fs::file_size(compiler, error);
    auto time = fs::last_write_time(compiler, error);
    return compiler.string() + " " + std::to_string(size) + " " + std::to_string(time.time_since_epoch().count());
}

}  // namespace

UnitObjectCache::UnitObjectCache(fs::path dir, const fs::path& compiler, const std::string& sharedDigest) : dir_(std::move(dir)) {
    ContentKey key;
    key.add(compilerIdentity(compiler));
    key.add(sharedDigest);
    inputsDigest_ = key.digest();
}

std::string UnitObjectCache::key(const std::string& path, const std::string& contents) const {
    ContentKey key;
    key.add(inputsDigest_);
    key.add(path);
    key.add(contents);
    return key.digest();
}

bool UnitObjectCache::fetch(const std::string& key, const fs::path& object, std::string* log) const {
    if (!enabled()) return false;
    const fs::path cached = dir_ / (key + ".o");
    std::error_code error;
    if (!fs::is_regular_file(cached, error) || !fs::is_regular_file(dir_ / (key + ".log"), error)) return false;
    *log = readBytes(dir_ / (key + ".log"));
    fs::copy_file(cached, object, fs::copy_options::overwrite_existing, error);
    if (error) return false;
    fs::last_write_time(cached, fs::file_time_type::clock::now(), error);  // recently used: trimmed last
    return true;
}

void UnitObjectCache::store(const std::string& key, const fs::path& object, const std::string& log) const {
    if (!enabled()) return;
    std::error_code error;
    fs::create_directories(dir_, error);
    if (error) return;
    // The messages first: an object is only fetched with its messages beside it.
    const fs::path logFile = dir_ / (key + ".log." + std::to_string(getpid()) + ".tmp");
    bool written;
    {
        std::ofstream out(logFile, std::ios::binary);
        written = static_cast<bool>(out << log << std::flush);
    }
    if (written) fs::rename(logFile, dir_ / (key + ".log"), error);
    if (!written || error) {
        fs::remove(logFile, error);
        return;
    }
    if (publishCopy(object, dir_ / (key + ".o"))) trim();
}

void UnitObjectCache::trim() const {
    struct Entry {
        fs::file_time_type used;
        fs::path object;
        std::uintmax_t bytes;
    };
    std::vector<Entry> entries;
    std::uintmax_t total = 0;
    std::error_code error;
    for (const auto& file : fs::directory_iterator(dir_, error)) {
        if (file.path().extension() != ".o") continue;
        std::uintmax_t bytes = file.file_size(error);
        if (error) continue;
        entries.push_back({file.last_write_time(error), file.path(), bytes});
        total += bytes;
    }
    if (total <= kUnitObjectCacheBytes) return;
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
    // Down to three quarters, so that the next few objects do not trim again.
    for (const Entry& entry : entries) {
        if (total <= kUnitObjectCacheBytes / 4 * 3) break;
        fs::remove(entry.object, error);
        fs::remove(fs::path(entry.object).replace_extension(".log"), error);
        total -= entry.bytes;
    }
}

}  // namespace rtlab::grader
