// A point light. glTF gives intensity in candela; the renderer works in radiometric units,
// I [W/sr] = cd / 683, as Blender's glTF importer does, or I = Phi / 4 pi for a light given by
// its power Phi in W (extras.rtlab.power; docs/conventions.md#lights-and-units). Lights with an
// area are emissive triangles and spheres (emitters.h).
#pragma once

#include "framework/core/vec.h"

#include <string>

namespace rtlab {

inline constexpr float kLumensPerWatt = 683.0f;

struct PointLight {
    std::string name;
    Vec3 position{0.0f};
    Vec3 intensity{0.0f};  // radiant intensity per channel [W/sr]
};

}  // namespace rtlab
