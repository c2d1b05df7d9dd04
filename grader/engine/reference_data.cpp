#include "grader/engine/reference_data.h"

#include "framework/core/error.h"
#include "framework/core/sha256.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace rtlab::grader {
namespace {

constexpr const char* kFile = "structures.json";
constexpr const char* kRegenerate = "an instructor must run `build/rtlab-solution grade --write-reference` (docs/grading.md)";

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

std::string sceneGeometrySha256(const Scene& scene) {
    std::string bytes;
    auto append = [&](const void* data, size_t size) { bytes.append(static_cast<const char*>(data), size); };
    const auto& t = scene.triangles;
    append(t.positions.data(), t.positions.size() * sizeof(Vec3));
    append(t.indices.data(), t.indices.size() * sizeof(t.indices[0]));
    for (const Sphere& s : scene.spheres) {
        append(&s.centre, sizeof s.centre);
        append(&s.radius, sizeof s.radius);
    }
    return sha256Hex(bytes);
}

ReferenceData ReferenceData::load(const std::string& directory) {
    ReferenceData data;
    data.directory_ = directory;
    std::string path = directory + "/" + kFile, manifestPath = directory + "/manifest.json";
    if (!std::filesystem::exists(path)) {
        data.problem_ = path + " does not exist; " + kRegenerate;
        return data;
    }
    std::string text = readFile(path);
    try {
        auto manifest = nlohmann::json::parse(readFile(manifestPath));
        if (manifest.value(kFile, std::string()) != sha256Hex(text)) {
            data.problem_ = path + " does not match the SHA-256 in " + manifestPath + "; " + kRegenerate;
            return data;
        }
        auto json = nlohmann::json::parse(text);
        for (const auto& [key, value] : json.at("entries").items())
            data.entries_[key] = StructureReference{
                value.at("scene_sha256").get<std::string>(),
                value.contains("cost") ? std::optional<double>(value.at("cost").get<double>()) : std::nullopt,
                value.at("closest_work_per_ray").get<double>(), value.at("occluded_work_per_ray").get<double>()};
    } catch (const nlohmann::json::exception& e) {
        data.problem_ = path + " or its manifest is malformed (" + e.what() + "); " + kRegenerate;
        data.entries_.clear();
    }
    return data;
}

ReferenceData ReferenceData::forWriting(const std::string& directory) {
    // Entries of scenes this run does not grade (the bunny or its stand-in) are kept.
    ReferenceData data = load(directory);
    data.problem_.clear();
    data.writing_ = true;
    return data;
}

std::optional<StructureReference> ReferenceData::find(const std::string& key, const std::string& sceneSha256,
                                                std::string* whyNot) const {
    if (!problem_.empty()) {
        *whyNot = problem_;
        return std::nullopt;
    }
    auto it = entries_.find(key);
    if (it == entries_.end()) {
        *whyNot = "no reference value for " + key + "; " + kRegenerate;
        return std::nullopt;
    }
    if (it->second.sceneSha256 != sceneSha256) {
        *whyNot = "the reference for " + key + " was made from a different scene; " + kRegenerate;
        return std::nullopt;
    }
    return it->second;
}

void ReferenceData::save() const {
    nlohmann::ordered_json json;
    json["generated_by"] = "rtlab-solution grade --write-reference";
    json["entries"] = nlohmann::ordered_json::object();
    for (const auto& [key, value] : entries_) {
        nlohmann::ordered_json entry{{"scene_sha256", value.sceneSha256}};
        if (value.cost) entry["cost"] = *value.cost;
        entry["closest_work_per_ray"] = value.closestWorkPerRay;
        entry["occluded_work_per_ray"] = value.occludedWorkPerRay;
        json["entries"][key] = entry;
    }
    std::filesystem::create_directories(directory_);
    std::string text = json.dump(1) + "\n";
    std::string path = directory_ + "/" + kFile;
    std::ofstream(path, std::ios::binary) << text;
    nlohmann::ordered_json manifest;
    manifest[kFile] = sha256Hex(text);
    std::ofstream(directory_ + "/manifest.json", std::ios::binary) << manifest.dump(1) << "\n";
    if (!std::filesystem::exists(path)) throw Error(path + ": cannot write the reference data");
}

}  // namespace rtlab::grader
