#include "grader/engine/worker_sources.h"

#include "framework/core/error.h"
#include "framework/core/sha256.h"
#include "grader/engine/assignment_registry.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// A manifest lists a few dozen files; one larger than this is not one the build wrote.
constexpr std::streamsize kMaxManifestBytes = 1 << 16;

// "<folder>/<file>" -> SHA-256, from the manifest beside the worker; empty when there is none.
std::map<std::string, std::string> readWorkerSources(const std::string& workerPath) {
    std::map<std::string, std::string> sources;
    std::ifstream in(workerSourcesPath(workerPath), std::ios::binary);
    if (!in) return sources;
    std::string text(size_t(kMaxManifestBytes) + 1, '\0');
    in.read(text.data(), kMaxManifestBytes + 1);
    if (in.gcount() > kMaxManifestBytes) return {};
    text.resize(size_t(in.gcount()));
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        size_t space = line.find(' ');
        if (space == 64) sources[line.substr(65)] = line.substr(0, 64);
    }
    return sources;
}

}  // namespace

std::string workerSourcesPath(const std::string& workerPath) { return workerPath + ".sources"; }

void writeWorkerSources(const std::string& root, const std::string& workerPath) {
    std::map<std::string, std::string> sources;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file() && entry.path().extension() == ".cpp")
            sources[entry.path().lexically_relative(root).generic_string()] = sha256OfFile(entry.path().string());
    std::ofstream out(workerSourcesPath(workerPath), std::ios::binary | std::ios::trunc);
    for (const auto& [file, digest] : sources) out << digest << ' ' << file << '\n';
    if (!out.flush()) throw Error(workerSourcesPath(workerPath) + ": cannot write the worker's list of sources");
}

std::set<std::string> unstartedStubs(const std::map<std::string, std::string>& committed, const std::string& workerPath) {
    std::set<std::string> unstarted;
    if (committed.empty()) return unstarted;
    const std::map<std::string, std::string> sources = readWorkerSources(workerPath);
    for (const Assignment& assignment : assignments()) {
        const StubTable& table = assignment.stubs();
        for (const StubFile& file : table.files()) {
            auto stub = committed.find(table.path(file.file));
            auto held = sources.find(table.folder() + "/" + file.file);
            if (stub == committed.end() || held == sources.end() || held->second != sha256Hex(stub->second)) continue;
            for (const std::string& function : file.functions) unstarted.insert(table.name(function));
        }
    }
    return unstarted;
}

}  // namespace rtlab::grader
