#include "framework/render/image_io.h"

#include "framework/core/error.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace rtlab {
namespace {

namespace fs = std::filesystem;

enum class FileKind { Exr, Png };

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

// OpenImageIO's messages may span lines; the CLI promises one.
std::string oneLine(std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    while (!message.empty() && message.back() == ' ') message.pop_back();
    return message;
}

FileKind fileKindOf(const std::string& path) {
    std::string extension = lowercase(fs::path(path).extension().string());
    if (extension == ".exr") return FileKind::Exr;
    if (extension == ".png") return FileKind::Png;
    throw Error(path + ": unsupported image extension '" + extension + "' (use .exr or .png)");
}

template <typename Code, typename Encode>
std::vector<Code> quantise(const Image& image, Encode encode) {
    std::vector<Code> codes(image.pixels.size());
    std::transform(image.pixels.begin(), image.pixels.end(), codes.begin(), encode);
    return codes;
}

void writeWithOiio(const std::string& path, const Image& image, OIIO::TypeDesc type, const void* data,
                   const char* colourSpace) {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) throw Error(path + ": " + oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec(image.width, image.height, image.channels, type);
    spec.attribute("oiio:ColorSpace", colourSpace);
    if (type == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
    if (!output->open(path, spec) || !output->write_image(type, data) || !output->close())
        throw Error(path + ": " + oneLine(output->geterror()));
}

}  // namespace

uint16_t encodeLinear16(float value) {
    // POV-Ray 3.7's IntEncode (base/image/encoding.h): floor(clip(v) * 65535.0f + 0.5f) with
    // both steps rounded to float; NaN -> 0. Each step is done exactly in double and rounded to
    // float once, which is what the float operation gives, and no fused multiply-add can
    // change it. Near k + 0.5 this differs from exact arithmetic, as POV-Ray does.
    float clipped = std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, 1.0f);
    auto scaled = static_cast<float>(static_cast<double>(clipped) * 65535.0);
    auto rounded = static_cast<float>(static_cast<double>(scaled) + 0.5);
    return static_cast<uint16_t>(std::floor(rounded));
}

uint8_t encodeSrgb8(float value, float exposure) {
    float exposed = value * std::exp2(exposure);
    float linear = std::isnan(exposed) ? 0.0f : std::clamp(exposed, 0.0f, 1.0f);
    float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<uint8_t>(std::floor(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f));
}

void checkImageOutput(const std::string& path, const ImageWriteOptions& options) {
    FileKind kind = fileKindOf(path);
    if (options.srgb8 && kind != FileKind::Png) throw Error(path + ": 8-bit sRGB output needs a .png file");
    if (options.exposure != 0.0f && !options.srgb8)
        throw Error(path + ": --exposure applies to 8-bit sRGB output only (linear files keep radiometric values)");
    if (!std::isfinite(options.exposure)) throw Error(path + ": the exposure must be a finite number");
    fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent))
        throw Error(path + ": directory " + parent.string() + " does not exist");
    if (fs::is_directory(path)) throw Error(path + ": is a directory");
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
    checkImageOutput(path, options);
    if (fileKindOf(path) == FileKind::Exr) {
        writeWithOiio(path, image, OIIO::TypeDesc::FLOAT, image.pixels.data(), "Linear");
    } else if (options.srgb8) {
        auto codes = quantise<uint8_t>(image, [&](float v) { return encodeSrgb8(v, options.exposure); });
        writeWithOiio(path, image, OIIO::TypeDesc::UINT8, codes.data(), "sRGB");
    } else {
        auto codes = quantise<uint16_t>(image, encodeLinear16);
        writeWithOiio(path, image, OIIO::TypeDesc::UINT16, codes.data(), "Linear");
    }
}

Image readImage(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) throw Error(path + ": " + oneLine(OIIO::geterror()));
    const OIIO::ImageSpec& spec = input->spec();
    Image image(spec.width, spec.height, spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw Error(path + ": " + oneLine(input->geterror()));
    return image;
}

}  // namespace rtlab
