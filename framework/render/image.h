// A float image in memory: width x height pixels of `channels` interleaved floats, row 0 at
// the top (as image files store them). The renderer's colour output is linear RGB radiance.
#pragma once

#include "framework/core/vec.h"
#include "framework/core/zeroed_allocator.h"

#include <cstddef>
#include <vector>

namespace rtlab {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    // (y * width + x) * channels + c; zero from calloc, not written twice (zeroed_allocator.h)
    std::vector<float, ZeroedAllocator<float>> pixels;

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(static_cast<size_t>(w) * h * c) {}

    size_t index(int x, int y) const { return (static_cast<size_t>(y) * width + x) * channels; }
    float& at(int x, int y, int c) { return pixels[index(x, y) + c]; }
    float at(int x, int y, int c) const { return pixels[index(x, y) + c]; }

    // For RGB images.
    Vec3 rgb(int x, int y) const {
        size_t i = index(x, y);
        return {pixels[i], pixels[i + 1], pixels[i + 2]};
    }
    void setRgb(int x, int y, const Vec3& v) {
        size_t i = index(x, y);
        pixels[i] = v.x;
        pixels[i + 1] = v.y;
        pixels[i + 2] = v.z;
    }
};

}  // namespace rtlab
