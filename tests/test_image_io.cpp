// Image files written through OpenImageIO and read back: the quantisation rules of
// framework/render/image_io.h (the same as POV-Ray's), EXR range, the sRGB curve, and the
// one-line errors for bad paths.
#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/render/image_io.h"
#include "tests/output_dirs.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <vector>

using namespace rtlab;
namespace fs = std::filesystem;

static fs::path outputDir() { return test::outputDir("image_io"); }

// Reads the file's integer codes directly, with no conversion.
template <typename Code>
static std::vector<Code> readCodes(const fs::path& path, OIIO::TypeDesc expected, int* channels) {
    auto input = OIIO::ImageInput::open(path.string());
    REQUIRE(input);
    const OIIO::ImageSpec& spec = input->spec();
    CHECK(spec.format == expected);
    *channels = spec.nchannels;
    std::vector<Code> codes(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    REQUIRE(input->read_image(0, 0, 0, spec.nchannels, expected, codes.data()));
    return codes;
}

// One row of values, as an RGB image (channel c of pixel x = values[3x + c]).
static Image rowImage(const std::vector<float>& values) {
    REQUIRE(values.size() % 3 == 0);
    Image image(static_cast<int>(values.size() / 3), 1, 3);
    image.pixels.assign(values.begin(), values.end());
    return image;
}

TEST_CASE("16-bit PNG: code = floor(clip(v,0,1)*65535 + 0.5), read back unchanged") {
    // Values at known offsets from code k, away from the rounding boundary k + 0.5 so that the
    // exact (double) formula is unambiguous; plus clipping cases.
    Pcg32 random(7, 1);
    std::vector<float> values{0.0f, 1.0f, -0.25f, 1.5f, 1e-9f, 0.4f};
    // 0.4 -> 26214 (docs/conventions.md#lights-and-units)
    std::vector<uint16_t> expected{0, 65535, 0, 65535, 0, 26214};
    const double fractions[] = {0.0, 0.25, 0.49, 0.51, 0.75, 0.999};
    for (int i = 0; i < 600; ++i) {
        uint32_t k = random.next() % 65535;
        float v = static_cast<float>((k + fractions[i % 6]) / 65535.0);
        values.push_back(v);
        expected.push_back(static_cast<uint16_t>(std::floor(static_cast<double>(v) * 65535.0 + 0.5)));
    }
    fs::path path = outputDir() / "codes16.png";
    writeImage(path.string(), rowImage(values));
    int channels = 0;
    std::vector<uint16_t> codes = readCodes<uint16_t>(path, OIIO::TypeDesc::UINT16, &channels);
    CHECK(channels == 3);
    REQUIRE(codes.size() == expected.size());
    for (size_t i = 0; i < codes.size(); ++i) {
        INFO("value ", values[i]);
        CHECK(codes[i] == expected[i]);
    }
    // Read as float, a code comes back as code / 65535.
    Image back = readImage(path.string());
    CHECK(back.pixels[5] == doctest::Approx(26214.0 / 65535.0).epsilon(1e-7));
}

TEST_CASE("16-bit codes next to k + 0.5 round as POV-Ray's float IntEncode, not as exact arithmetic") {
    // POV-Ray computes floor(v * 65535.0f + 0.5f) in float; volatile forces each float rounding
    // here (no fused multiply-add).
    Pcg32 random(11, 2);
    int differFromExact = 0;
    for (int i = 0; i < 20000; ++i) {
        uint32_t k = random.next() % 65535;
        float v = static_cast<float>((k + 0.5 + (random.uniform() - 0.5) * 1e-5) / 65535.0);
        volatile float scaled = v * 65535.0f;
        volatile float rounded = scaled + 0.5f;
        auto povCode = static_cast<uint16_t>(std::floor(rounded));
        CHECK(encodeLinear16(v) == povCode);
        differFromExact += povCode != static_cast<uint16_t>(std::floor(static_cast<double>(v) * 65535.0 + 0.5));
    }
    CHECK(differFromExact > 0);  // the cases really sit on the boundary
}

TEST_CASE("EXR keeps values above 1 and infinity exactly (float32)") {
    std::vector<float> values{0.1f, 3.75f, 1e6f, 0.0f, kInfinity, 1.0f / 3.0f};
    fs::path path = outputDir() / "range.exr";
    writeImage(path.string(), rowImage(values));
    Image back = readImage(path.string());
    REQUIRE(back.pixels.size() == values.size());
    for (size_t i = 0; i < values.size(); ++i) CHECK(back.pixels[i] == values[i]);

    auto input = OIIO::ImageInput::open(path.string());
    REQUIRE(input);
    CHECK(input->spec().format == OIIO::TypeDesc::FLOAT);
}

static int srgbCode(double linear) {
    double c = std::clamp(linear, 0.0, 1.0);
    double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::floor(encoded * 255.0 + 0.5));
}

TEST_CASE("8-bit sRGB PNG applies exposure, then the sRGB curve") {
    std::vector<float> values{0.0f, 0.001f, 0.18f, 0.5f, 1.0f, 2.0f};
    fs::path path = outputDir() / "srgb.png";
    int channels = 0;

    writeImage(path.string(), rowImage(values), {.srgb8 = true});
    std::vector<uint8_t> codes = readCodes<uint8_t>(path, OIIO::TypeDesc::UINT8, &channels);
    std::vector<int> expected{0, 3, 118, 188, 255, 255};
    for (size_t i = 0; i < values.size(); ++i) {
        CHECK(srgbCode(values[i]) == expected[i]);  // the figures above are the curve's
        CHECK(codes[i] == expected[i]);
    }

    writeImage(path.string(), rowImage(values), {.srgb8 = true, .exposure = -1.0f});
    codes = readCodes<uint8_t>(path, OIIO::TypeDesc::UINT8, &channels);
    for (size_t i = 0; i < values.size(); ++i) CHECK(codes[i] == srgbCode(values[i] * 0.5));
}

TEST_CASE("bad output paths and options give one-line errors") {
    Image image(2, 2, 3);
    std::string missingDir = (outputDir() / "no-such-dir" / "out.png").string();
    CHECK_THROWS_WITH_AS(writeImage(missingDir, image), doctest::Contains("does not exist"), Error);
    CHECK_THROWS_WITH_AS(writeImage((outputDir() / "out.jpg").string(), image),
                         doctest::Contains("unsupported image extension"), Error);
    CHECK_THROWS_AS(writeImage((outputDir() / "out.exr").string(), image, {.srgb8 = true}), Error);
    CHECK_THROWS_AS(writeImage((outputDir() / "out.png").string(), image, {.exposure = 1.0f}), Error);
    CHECK_THROWS_AS(writeImage(outputDir().string() + "/", image), Error);
    try {
        writeImage(missingDir, image);
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
    CHECK_THROWS_AS(readImage((outputDir() / "missing.png").string()), Error);
}
