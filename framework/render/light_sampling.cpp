#include "framework/render/light_sampling.h"

#include "framework/core/error.h"

namespace rtlab {

const char* lightSamplingName(LightSampling sampling) {
    switch (sampling) {
        case LightSampling::Area: return "area";
        case LightSampling::SolidAngle: return "solid-angle";
        case LightSampling::Hemisphere: return "hemisphere";
        case LightSampling::Cosine: return "cosine";
    }
    return "?";
}

LightSampling parseLightSampling(const std::string& name) {
    std::string valid;
    for (LightSampling sampling : kLightSamplings) {
        if (name == lightSamplingName(sampling)) return sampling;
        valid += (valid.empty() ? "" : ", ") + std::string(lightSamplingName(sampling));
    }
    throw Error("unknown light sampling '" + name + "' (valid: " + valid + ")");
}

}  // namespace rtlab
