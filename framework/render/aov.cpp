#include "framework/render/aov.h"

#include "framework/core/error.h"
#include "framework/core/hit.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtlab {

Aov parseAov(const std::string& name) {
    for (Aov aov : {Aov::Normal, Aov::Depth, Aov::Primitive, Aov::Cost, Aov::Steps})
        if (name == aovName(aov)) return aov;
    throw Error("--aov " + name + " is not an AOV (valid: normal, depth, prim, cost, steps)");
}

const char* aovName(Aov aov) {
    switch (aov) {
    case Aov::Normal: return "normal";
    case Aov::Depth: return "depth";
    case Aov::Primitive: return "prim";
    case Aov::Cost: return "cost";
    case Aov::Steps: return "steps";
    }
    return "?";
}

Vec3 primitiveColour(uint32_t prim) {
    // The murmur3 finaliser: every input bit affects every output bit.
    uint32_t h = prim;
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    // Three bytes, kept away from black so no primitive looks like background.
    auto channel = [](uint32_t byte) { return 0.2f + 0.8f * static_cast<float>(byte & 0xffu) / 255.0f; };
    return {channel(h), channel(h >> 8), channel(h >> 16)};
}

Vec3 heatColour(float x) {
    static constexpr std::array<Vec3, 5> kStops = {
        Vec3(0.0f, 0.0f, 0.015f), Vec3(0.34f, 0.06f, 0.43f), Vec3(0.73f, 0.21f, 0.33f),
        Vec3(0.98f, 0.55f, 0.04f), Vec3(0.99f, 1.0f, 0.64f)};
    float position = std::clamp(std::isnan(x) ? 0.0f : x, 0.0f, 1.0f) * (kStops.size() - 1);
    size_t lower = std::min(static_cast<size_t>(position), kStops.size() - 2);
    float fraction = position - static_cast<float>(lower);
    return glm::mix(kStops[lower], kStops[lower + 1], fraction);
}

uint32_t maxCount(const std::vector<uint32_t>& counts) {
    return counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
}

static Image depthImage(const Image& depth, bool integerFile) {
    if (!integerFile) return depth;
    float farthest = 0.0f;
    for (float t : depth.pixels)
        if (std::isfinite(t)) farthest = std::max(farthest, t);
    Image scaled = depth;
    for (float& t : scaled.pixels) t = (std::isfinite(t) && farthest > 0.0f) ? t / farthest : 0.0f;
    return scaled;
}

Image aovImage(Aov aov, const AovBuffers& buffers, int width, int height, bool integerFile) {
    switch (aov) {
    case Aov::Normal: return buffers.normal;
    case Aov::Depth: return depthImage(buffers.depth, integerFile);
    case Aov::Primitive:
    case Aov::Cost:
    case Aov::Steps: break;
    }
    Image image(width, height, 3);
    const std::vector<uint32_t>& counts = aov == Aov::Steps ? buffers.steps : buffers.cost;
    float scale = 1.0f / static_cast<float>(std::max(maxCount(counts), 1u));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            size_t i = static_cast<size_t>(y) * width + x;
            if (aov != Aov::Primitive) {
                image.setRgb(x, y, heatColour(static_cast<float>(counts[i]) * scale));
            } else if (buffers.primitive[i] != kNoHit) {
                image.setRgb(x, y, primitiveColour(buffers.primitive[i]));
            }
        }
    }
    return image;
}

}  // namespace rtlab
