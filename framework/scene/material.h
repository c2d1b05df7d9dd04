// A Lambertian material: reflects albedo/pi of the incident irradiance in every direction,
// and may emit radiance of its own. A triangle with an emissive material is an area light; a
// sphere with one is a sphere light (docs/conventions.md#lights-and-units).
#pragma once

#include "framework/core/vec.h"

#include <string>

namespace rtlab {

struct Material {
    std::string name;
    Vec3 albedo{0.8f};    // glTF baseColorFactor (rgb)
    Vec3 emission{0.0f};  // radiance [W/(sr m^2)]: emissiveFactor * KHR_materials_emissive_strength
    bool doubleSided = false;  // glTF doubleSided: triangles emit on both faces, not only the front
};

}  // namespace rtlab
