// Writes a Scene as glTF 2.0 (docs/scenes.md): binary .glb when the path ends in ".glb",
// otherwise .gltf with the buffer embedded. The result loads back through loadGltf into the
// same scene: world-space triangles (one mesh, one primitive per material, identity node),
// Lambert materials, perspective cameras, point lights (KHR_lights_punctual, candela) and
// analytic spheres (extras.rtlab.sphere).
#pragma once

#include "framework/scene/scene.h"

#include <string>

namespace rtlab {

// Throws rtlab::Error with one line naming the path when it cannot be written.
void writeGltf(const Scene& scene, const std::string& path);

}  // namespace rtlab
