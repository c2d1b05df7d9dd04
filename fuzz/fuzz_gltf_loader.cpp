// libFuzzer target: loadGltf on one file, .gltf (JSON) or .glb (binary) by its first bytes, as
// the loader itself decides. A loaded scene is walked, so a loader that hands over indices it
// did not check shows up under AddressSanitizer here.
#include "framework/scene/gltf_loader.h"
#include "fuzz/input_file.h"
#include "fuzz/one_line_error.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rtlab;
    std::string path = fuzz::writeInputFile("input.gltf", data, size);
    fuzz::parseOrReject(path, [](const std::string& file) {
        Scene scene = loadGltf(file);
        const Triangles& t = scene.triangles;
        for (size_t i = 0; i < t.indices.size(); ++i) {
            for (uint32_t v : t.indices[i])
                if (v >= t.positions.size() || (!t.normals.empty() && v >= t.normals.size())) std::abort();
            if (t.material[i] >= scene.materials.size()) std::abort();
        }
        for (const Sphere& sphere : scene.spheres)
            if (sphere.material >= scene.materials.size()) std::abort();
    });
    return 0;
}
