// Image comparison through OpenImageIO (framework/verification/image_compare.h) and `rtlab compare`,
// on 16-bit PNGs with known differences in codes.
#include "framework/core/error.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "tests/cli_runner.h"
#include "tests/output_dirs.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <vector>

using namespace rtlab;
namespace fs = std::filesystem;

static fs::path outputDir() { return test::outputDir("image_compare"); }

static Image uniform(int width, int height, double code) {
    Image image(width, height, 3);
    for (float& v : image.pixels) v = static_cast<float>(code / 65535.0);
    return image;
}

static void addCodes(Image& image, int x, int y, int c, int codes) {
    image.at(x, y, c) = static_cast<float>((std::round(image.at(x, y, c) * 65535.0) + codes) / 65535.0);
}

// 10x10 mid grey; B differs by 1 code at (1,1) red, 2 codes at (2,2) green, 300 at (3,3) blue.
struct KnownPair {
    Image a = uniform(10, 10, 32768);
    Image b = uniform(10, 10, 32768);
    fs::path pathA = outputDir() / "a.png";
    fs::path pathB = outputDir() / "b.png";

    KnownPair() {
        addCodes(b, 1, 1, 0, 1);
        addCodes(b, 2, 2, 1, 2);
        addCodes(b, 3, 3, 2, 300);
        writeImage(pathA.string(), a);
        writeImage(pathB.string(), b);
    }
};

TEST_CASE("image compare: errors in 16-bit codes, median, share over the threshold") {
    KnownPair pair;
    ImageComparison c = compareImages(pair.pathA.string(), pair.pathB.string(), 2.0);
    CHECK(c.width == 10);
    CHECK(c.height == 10);
    CHECK(c.channels == 3);
    CHECK(c.wholeCodes);
    CHECK(c.maxCodes() == 300.0);
    CHECK(c.maxX == 3);
    CHECK(c.maxY == 3);
    CHECK(c.meanCodes() == doctest::Approx(303.0 / 300.0).epsilon(1e-4));
    CHECK(c.medianPixelCodes == 0.0);
    CHECK(c.pixelsByCodes == std::array<uint64_t, 4>{97, 1, 1, 1});
    CHECK(c.pixelsOverThreshold == 1);
    CHECK(c.shareOverThreshold() == doctest::Approx(0.01));
    CHECK(c.rmse == doctest::Approx(std::sqrt((1.0 + 4.0 + 90000.0) / 300.0) / 65535.0).epsilon(1e-4));
    CHECK(c.psnr == doctest::Approx(20.0 * std::log10(1.0 / c.rmse)));

    ImageComparison strict = compareImages(pair.pathA.string(), pair.pathB.string(), 0.0);
    CHECK(strict.pixelsOverThreshold == 3);

    // In memory: the same figures from the float images.
    ImageComparison inMemory = compareImages(pair.a, pair.b, 2.0);
    CHECK(inMemory.pixelsOverThreshold == 1);
    CHECK(inMemory.maxCodes() == doctest::Approx(300.0).epsilon(1e-4));
}

TEST_CASE("image compare: identical images, and one-line errors for bad input") {
    KnownPair pair;
    ImageComparison same = compareImages(pair.pathA.string(), pair.pathA.string());
    CHECK(same.maxCodes() == 0.0);
    CHECK(same.pixelsByCodes[0] == 100);
    CHECK(std::isinf(same.psnr));

    fs::path small = outputDir() / "small.png";
    writeImage(small.string(), uniform(4, 4, 0));
    CHECK_THROWS_AS(compareImages(pair.pathA.string(), small.string()), Error);
    CHECK_THROWS_AS(compareImages(pair.pathA.string(), (outputDir() / "missing.png").string()), Error);
}

TEST_CASE("image compare: the heat map colours pixels by their error band") {
    KnownPair pair;
    fs::path heat = outputDir() / "heat.png";
    writeErrorHeatMap(pair.pathA.string(), pair.pathB.string(), heat.string());
    Image map = readImage(heat.string());
    REQUIRE(map.width == 10);
    Vec3 equal = map.rgb(0, 0), one = map.rgb(1, 1), two = map.rgb(2, 2), many = map.rgb(3, 3);
    CHECK(equal.r == equal.g);  // grey
    CHECK(equal.r < 0.4f);
    CHECK(one.b > 0.9f);  // blue
    CHECK(two.g > 0.8f);  // green
    CHECK(two.r < 0.1f);
    CHECK(many.r > 0.9f);  // red: 256 codes or more
    CHECK(many.g < 0.1f);
}

TEST_CASE("rtlab compare: exit status follows the tolerances given") {
    KnownPair pair;
    std::string a = pair.pathA.string(), b = pair.pathB.string();
    CHECK(test::runCliStatus({"compare", a, b}) == 0);
    CHECK(test::runCliStatus({"compare", a, b, "--max-max", "300"}) == 0);
    CHECK(test::runCliStatus({"compare", a, b, "--max-max", "299"}) != 0);
    CHECK(test::runCliStatus({"compare", a, b, "--max-share", "0.01"}) == 0);
    CHECK(test::runCliStatus({"compare", a, b, "--max-share", "0.009"}) != 0);
    CHECK(test::runCliStatus({"compare", a, b, "--threshold", "300", "--max-share", "0"}) == 0);
    CHECK(test::runCliStatus({"compare", a, b, "--max-mean", "1"}) != 0);
    fs::path heat = outputDir() / "cli_heat.png";
    fs::remove(heat);
    CHECK(test::runCliStatus({"compare", a, b, "--diff", heat.string()}) == 0);
    CHECK(fs::exists(heat));
    CHECK(test::runCliStatus({"compare", a, (outputDir() / "missing.png").string()}) != 0);
}
