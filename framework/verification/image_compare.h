// Comparing two images through OpenImageIO (docs/verification.md): a render against its
// POV-Ray reference, a student render against the solution's. Differences are reported in
// image units (1 = white) and in 16-bit codes (difference x 65535), the unit of our PNGs and
// POV-Ray's; only the colour channels (at most the first three) are compared.
#pragma once

#include "framework/render/image.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

inline constexpr double kCodesPerUnit = 65535.0;

struct ImageComparison {
    int width = 0;
    int height = 0;
    int channels = 0;  // colour channels compared

    // Over every compared channel value (ImageBufAlgo::compare), in image units.
    double meanError = 0.0;
    double maxError = 0.0;
    double rmse = 0.0;
    double psnr = 0.0;  // 20 log10(1 / rmse) dB; +inf for identical images
    int maxX = 0;       // a pixel with the largest error
    int maxY = 0;

    // Per pixel, the largest error of its channels in 16-bit codes. For two integer 16-bit
    // images the codes are whole numbers.
    double medianPixelCodes = 0.0;
    double thresholdCodes = 0.0;
    uint64_t pixelCount = 0;
    uint64_t pixelsOverThreshold = 0;  // pixels with a channel off by more than thresholdCodes
    // Pixels whose error is 0, at most 1, at most 2, more than 2 codes.
    std::array<uint64_t, 4> pixelsByCodes{};

    bool wholeCodes = false;  // both images hold 16-bit integer codes

    double meanCodes() const { return meanError * kCodesPerUnit; }
    // OpenImageIO compares in float; for two 16-bit images the max is a whole number of codes.
    double maxCodes() const {
        return wholeCodes ? std::round(maxError * kCodesPerUnit) : maxError * kCodesPerUnit;
    }
    double shareOverThreshold() const {
        return pixelCount ? static_cast<double>(pixelsOverThreshold) / pixelCount : 0.0;
    }
};

// Compares two image files (any format OpenImageIO reads). Throws rtlab::Error with one line
// when a file cannot be read, the sizes differ (naming the --width/--height that fit the
// second) or only one of them is 8-bit (an sRGB PNG for viewing; naming --linear16).
ImageComparison compareImages(const std::string& pathA, const std::string& pathB,
                              double thresholdCodes = 2.0);
ImageComparison compareImages(const Image& a, const Image& b, double thresholdCodes = 2.0);

// A re-rendered image against the committed one it should reproduce: identical pixels, or
// the RMS of their difference over the committed image's mean (its channels' average) within
// relativeRmsTolerance (0 demands identical pixels).
struct ImageAgreement {
    bool identical = false;
    bool agrees = false;
    double relativeRms = 0.0;  // 0 when identical
};
ImageAgreement agreementWith(const ImageComparison& comparison, const std::string& committedPath, double relativeRmsTolerance);

// Writes an 8-bit PNG the size of the images. Both images are first quantised to 16-bit codes
// (encodeLinear16, as our PNGs and POV-Ray's references are), so differences below a code that
// round alike are equal: those pixels show image A as dim grey, the others are coloured by
// their error in codes (errorHeatMapBands()). The path variants refuse, with a hint, images of
// different sizes and an 8-bit image against a 16-bit or float one, as compareImages does.
void writeErrorHeatMap(const std::string& pathA, const std::string& pathB, const std::string& heatMapPath);
void writeErrorHeatMap(const Image& a, const Image& b, const std::string& heatMapPath);

// A colour of the heat map and the error it means: errors up to maxCodes (and above the
// previous band's) in 16-bit codes.
struct HeatMapBand {
    double maxCodes;
    float rgb[3];  // sRGB display colour, 0..1
    std::string colourName;
    std::string meaning;
};
const std::vector<HeatMapBand>& errorHeatMapBands();

// One line naming the heat map's colours, for reports.
std::string errorHeatMapLegend();

}  // namespace rtlab
