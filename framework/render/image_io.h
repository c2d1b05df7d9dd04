// Image files through OpenImageIO (docs/rendering.md, "Outputs"). The format follows the
// extension:
//   .exr  linear float32, values kept as they are (also > 1 and +inf)
//   .png  16-bit linear: code = floor(clip(v, 0, 1) * 65535 + 0.5), in float arithmetic
//         exactly as POV-Ray's IntEncode, so codes compare one to one with POV-Ray references
//   .png with srgb8  8-bit sRGB for viewing: v * 2^exposure, then the sRGB curve, then
//         floor(clip(c, 0, 1) * 255 + 0.5)
// Quantisation is done here, not by OpenImageIO, so the codes are exactly these.
#pragma once

#include "framework/render/image.h"

#include <cstdint>
#include <string>

namespace rtlab {

struct ImageWriteOptions {
    bool srgb8 = false;     // .png only
    float exposure = 0.0f;  // in stops (EV); only with srgb8
};

// Throws rtlab::Error (one line, naming the path) for an unknown extension, a directory that
// does not exist, or options that do not fit the format; lets a command fail before it renders.
void checkImageOutput(const std::string& path, const ImageWriteOptions& options = {});

// Checks as checkImageOutput, then writes; also throws rtlab::Error when the write fails.
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options = {});

// Reads any file OpenImageIO reads as float: integer codes become code / max, so a 16-bit
// PNG gives code / 65535. No colour conversion is applied.
Image readImage(const std::string& path);

uint16_t encodeLinear16(float value);
uint8_t encodeSrgb8(float value, float exposure = 0.0f);

}  // namespace rtlab
