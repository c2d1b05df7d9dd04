// Loads a glTF 2.0 scene (.gltf or .glb) with tinygltf (docs/scenes.md lists what is read).
// Any problem throws rtlab::Error with one line naming the file and the problem.
#pragma once

#include "framework/scene/scene.h"

#include <string>

namespace rtlab {

Scene loadGltf(const std::string& path);

}  // namespace rtlab
