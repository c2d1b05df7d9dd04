// How the renderer estimates the light of emissive triangles and spheres (`--light-sampling`,
// docs/rendering.md#area-and-sphere-lights): one light picked by power and sampled by its area
// or by the solid angle it subtends, or a direction about the normal (uniform or cosine-
// weighted) that finds whatever emitter it meets. Point lights are always computed exactly.
#pragma once

#include <array>
#include <string>

namespace rtlab {

enum class LightSampling { Area, SolidAngle, Hemisphere, Cosine };

inline constexpr std::array kLightSamplings = {LightSampling::Area, LightSampling::SolidAngle, LightSampling::Hemisphere,
                                               LightSampling::Cosine};

// "area" | "solid-angle" | "hemisphere" | "cosine"; throws rtlab::Error naming the valid ones.
LightSampling parseLightSampling(const std::string& name);
const char* lightSamplingName(LightSampling sampling);

}  // namespace rtlab
