#include "framework/pov/reference_manifest.h"

#include "framework/core/error.h"
#include "framework/core/sha256.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace rtlab {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kManifestFormat = 1;

json toJson(const ReferenceEntry& e) {
    return json{{"scene", e.scene},        {"inputs", e.inputs},     {"camera", e.camera},
                {"exporter", e.exporter},  {"povray", e.povray},     {"width", e.width},
                {"height", e.height},      {"settings", e.settings}, {"image", e.image},
                {"image_sha256", e.imageSha256}};
}

ReferenceEntry fromJson(const std::string& name, const json& j) {
    ReferenceEntry e;
    e.name = name;
    e.scene = j.at("scene").get<std::string>();
    e.inputs = j.at("inputs").get<std::map<std::string, std::string>>();
    e.camera = j.at("camera").get<std::string>();
    e.exporter = j.at("exporter").get<std::string>();
    e.povray = j.at("povray").get<std::string>();
    e.width = j.at("width").get<int>();
    e.height = j.at("height").get<int>();
    e.settings = j.at("settings").get<std::string>();
    e.image = j.at("image").get<std::string>();
    e.imageSha256 = j.at("image_sha256").get<std::string>();
    return e;
}

std::string relativeName(const fs::path& file, const fs::path& root) {
    return fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(root).lexically_normal()).generic_string();
}

}  // namespace

ReferenceManifest ReferenceManifest::load(const fs::path& path) {
    ReferenceManifest manifest;
    if (!fs::exists(path)) return manifest;
    std::ifstream in(path);
    try {
        json j = json::parse(in);
        if (j.at("format").get<int>() != kManifestFormat)
            throw Error(path.string() + ": manifest format " + j.at("format").dump() + " is not " +
                        std::to_string(kManifestFormat));
        for (const auto& [name, entry] : j.at("references").items()) manifest.entries[name] = fromJson(name, entry);
    } catch (const json::exception& e) {
        throw Error(path.string() + ": malformed reference manifest: " + e.what());
    }
    return manifest;
}

void ReferenceManifest::save(const fs::path& path) const {
    json references = json::object();
    for (const auto& [name, entry] : entries) references[name] = toJson(entry);
    json j{{"format", kManifestFormat},
           {"about", "POV-Ray references made by `rtlab refs` (docs/verification.md); do not edit"},
           {"references", references}};
    fs::path temporary = path;
    temporary += ".tmp";
    {
        std::ofstream out(temporary);
        out << j.dump(2) << "\n";
        if (!out) throw Error(temporary.string() + ": cannot write the reference manifest");
    }
    fs::rename(temporary, path);
}

std::map<std::string, std::string> hashSceneInputs(const fs::path& scene, const fs::path& root) {
    std::map<std::string, std::string> inputs;
    inputs[relativeName(scene, root)] = sha256OfFile(scene.string());
    if (scene.extension() != ".gltf") return inputs;
    std::ifstream in(scene);
    json gltf = json::parse(in, nullptr, false);
    if (gltf.is_discarded()) throw Error(scene.string() + ": not valid JSON");
    for (const char* kind : {"buffers", "images"}) {
        if (!gltf.contains(kind) || !gltf[kind].is_array()) continue;
        for (const json& item : gltf[kind]) {
            if (!item.contains("uri") || !item["uri"].is_string()) continue;
            std::string uri = item["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) continue;  // embedded: part of the scene file's hash
            fs::path file = scene.parent_path() / uri;
            inputs[relativeName(file, root)] = sha256OfFile(file.string());
        }
    }
    return inputs;
}

}  // namespace rtlab
