#include "framework/external/reference_policy.h"

#include "framework/core/sha256.h"

namespace rtlab {
namespace fs = std::filesystem;

std::string whyRender(const ReferenceEntry& wanted, const ReferenceManifest& manifest, const ReferenceFolder& folder,
                      const std::string& rendererName, bool force) {
    if (force) return "forced";
    auto found = manifest.entries.find(wanted.name);
    if (found == manifest.entries.end()) return "new";
    const ReferenceEntry& old = found->second;
    if (old.inputs != wanted.inputs || old.scene != wanted.scene) return "scene changed";
    if (old.exporter != wanted.exporter) return "exporter changed";
    if (old.renderer != wanted.renderer) return rendererName + " version changed";
    if (!old.sameRecipe(wanted)) return "settings changed";
    fs::path image = folder.refsDir / old.image;
    if (!fs::exists(image)) return "image missing";
    if (sha256OfFile(image.string()) != old.imageSha256) return "image modified";
    return "";
}

std::string staleReference(const std::string& name, const fs::path& scene, const ReferenceManifest& manifest,
                           const ReferenceFolder& folder) {
    auto found = manifest.entries.find(name);
    if (found == manifest.entries.end()) return "no reference in " + folder.manifestPath.string();
    const ReferenceEntry& entry = found->second;
    if (hashSceneInputs(scene, folder.root) != entry.inputs) return entry.scene + " changed since its reference was rendered";
    if (!fs::exists(folder.refsDir / entry.image)) return (folder.refsDir / entry.image).string() + " is missing";
    return "";
}

}  // namespace rtlab
