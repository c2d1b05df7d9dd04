#include "framework/external/reference_manifest.h"

#include "framework/core/error.h"
#include "framework/core/sha256.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>
#include <limits>

namespace rtlab {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Format 2 names the renderer's version "renderer"; format 1 (POV-Ray only) called it "povray".
constexpr int kManifestFormat = 2;

json toJson(const ReferenceEntry& e) {
    return json{{"scene", e.scene},        {"inputs", e.inputs},     {"camera", e.camera},
                {"exporter", e.exporter},  {"renderer", e.renderer},     {"width", e.width},
                {"height", e.height},      {"settings", e.settings}, {"image", e.image},
                {"image_sha256", e.imageSha256}};
}

// nlohmann's get<int>() casts whatever number it finds: 1e300 would be undefined behaviour and
// 4294967297 would read as 1. Only a whole number that fits an int is taken.
int wholeNumber(const json& value, const std::string& what) {
    if (!value.is_number_integer() || value.get<int64_t>() < 0 ||
        value.get<int64_t>() > std::numeric_limits<int>::max())
        throw Error(what + " must be a whole number from 0 to " + std::to_string(std::numeric_limits<int>::max()) +
                    ", not " + value.dump().substr(0, 40));
    return static_cast<int>(value.get<int64_t>());
}

ReferenceEntry fromJson(const std::string& path, int format, const std::string& name, const json& j) {
    // The name comes from the file: quoted and escaped as JSON, so the message stays one line.
    std::string where = path + ": reference " + json(name).dump(-1, ' ', false, json::error_handler_t::replace) + ": ";
    ReferenceEntry e;
    e.name = name;
    e.scene = j.at("scene").get<std::string>();
    e.inputs = j.at("inputs").get<std::map<std::string, std::string>>();
    e.camera = j.at("camera").get<std::string>();
    e.exporter = j.at("exporter").get<std::string>();
    e.renderer = j.at(format == 1 ? "povray" : "renderer").get<std::string>();
    e.width = wholeNumber(j.at("width"), where + "width");
    e.height = wholeNumber(j.at("height"), where + "height");
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
        int format = wholeNumber(j.at("format"), path.string() + ": manifest format");
        if (format != 1 && format != kManifestFormat)
            throw Error(path.string() + ": manifest format " + j.at("format").dump() + " is not 1 or " +
                        std::to_string(kManifestFormat));
        if (j.contains("about") && j["about"].is_string()) manifest.about = j["about"].get<std::string>();
        for (const auto& [name, entry] : j.at("references").items())
            manifest.entries[name] = fromJson(path.string(), format, name, entry);
    } catch (const json::exception& e) {
        throw Error(path.string() + ": malformed reference manifest: " + e.what());
    }
    return manifest;
}

void ReferenceManifest::save(const fs::path& path) const {
    json references = json::object();
    for (const auto& [name, entry] : entries) references[name] = toJson(entry);
    json j{{"format", kManifestFormat}, {"about", about}, {"references", references}};
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
