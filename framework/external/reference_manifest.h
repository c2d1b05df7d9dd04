// What each reference render was made from (scenes/refs/manifest.json for POV-Ray,
// scenes/refs/blender-manifest.json for Blender Cycles), so `rtlab refs` re-renders only what
// changed and anyone can tell how a reference came about. Paths are relative to the repository
// root (the parent of the scenes folder).
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace rtlab {

struct ReferenceEntry {
    std::string name;                           // image stem: scenes/refs/<name>.png
    std::string scene;                          // scene file
    std::map<std::string, std::string> inputs;  // SHA-256 of the scene file and the files it references
    std::string camera;
    std::string exporter;                       // the exporter's version (kPovExporterVersion, ...)
    std::string renderer;                       // the renderer's version line (`povray --version`, ...)
    int width = 0;
    int height = 0;
    std::string settings;                       // the renderer's settings that shape the image
    std::string image;                          // file name in the refs folder
    std::string imageSha256;

    bool sameRecipe(const ReferenceEntry& other) const {
        return scene == other.scene && inputs == other.inputs && camera == other.camera &&
               exporter == other.exporter && renderer == other.renderer && width == other.width &&
               height == other.height && settings == other.settings && image == other.image;
    }
};

struct ReferenceManifest {
    std::string about;                              // one line for the reader of the file
    std::map<std::string, ReferenceEntry> entries;  // by name

    // An empty manifest when the file does not exist; rtlab::Error when it is malformed.
    static ReferenceManifest load(const std::filesystem::path& path);
    // Writes atomically (temporary file, then rename).
    void save(const std::filesystem::path& path) const;
};

// SHA-256 of the scene file and of every external file a .gltf names (buffers, images), keyed
// by their paths relative to root.
std::map<std::string, std::string> hashSceneInputs(const std::filesystem::path& scene,
                                                   const std::filesystem::path& root);

}  // namespace rtlab
