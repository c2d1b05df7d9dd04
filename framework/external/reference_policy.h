// What the reference commands (rtlab refs) decide, apart from what they print: whether a
// scene's reference must be rendered again, and whether a committed reference is current
// enough to check anything against (docs/verification.md).
#pragma once

#include "framework/external/reference_manifest.h"

#include <filesystem>
#include <string>

namespace rtlab {

// Where a renderer's references live: the refs folder, its manifest, and the repository root
// that the manifest's scene paths are relative to.
struct ReferenceFolder {
    std::filesystem::path refsDir;
    std::filesystem::path manifestPath;
    std::filesystem::path root;
};

// Why the reference `wanted` describes must be rendered: "forced", "new", "scene changed",
// "exporter changed", "<rendererName> version changed", "settings changed", "image missing"
// or "image modified"; "" when the committed image is what that recipe makes.
std::string whyRender(const ReferenceEntry& wanted, const ReferenceManifest& manifest, const ReferenceFolder& folder,
                      const std::string& rendererName, bool force);

// Why the committed reference of the scene `name` (the file `scene`) cannot be checked
// against: "no reference in <manifest>", "<scene> changed since its reference was rendered",
// "<image> is missing"; "" when it is current.
std::string staleReference(const std::string& name, const std::filesystem::path& scene, const ReferenceManifest& manifest,
                           const ReferenceFolder& folder);

}  // namespace rtlab
