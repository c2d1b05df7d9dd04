#include "framework/verification/image_compare.h"

#include "framework/core/error.h"
#include "framework/render/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rtlab {
namespace {

OIIO::ImageBuf readBuffer(const std::string& path) {
    OIIO::ImageBuf buffer(path);
    if (!buffer.read(0, 0, true)) {
        std::string message = buffer.geterror();
        std::replace(message.begin(), message.end(), '\n', ' ');
        throw Error(path + ": cannot read the image: " + message);
    }
    return buffer;
}

// Two files compared by name: refused with a hint where the numbers would mean nothing, i.e.
// sizes that differ (usually a render at another size than its reference) or an 8-bit PNG for
// viewing against a linear image (sRGB codes are not radiance, and 8 bits are 257 16-bit codes).
void checkComparable(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const std::string& pathA, const std::string& pathB) {
    const OIIO::ImageSpec& sa = a.spec();
    const OIIO::ImageSpec& sb = b.spec();
    if (sa.width != sb.width || sa.height != sb.height)
        throw Error(pathA + " vs " + pathB + ": the images differ in size (" + std::to_string(sa.width) + "x" +
                    std::to_string(sa.height) + " and " + std::to_string(sb.width) + "x" + std::to_string(sb.height) +
                    "); render one at the second's size with rtlab render SCENE -o OUT.png --linear16 --width " +
                    std::to_string(sb.width) + " --height " + std::to_string(sb.height));
    bool eightA = sa.format == OIIO::TypeDesc::UINT8, eightB = sb.format == OIIO::TypeDesc::UINT8;
    if (eightA != eightB)
        throw Error((eightA ? pathA : pathB) + ": an 8-bit image (sRGB, for viewing) cannot be compared with " +
                    (eightA ? pathB : pathA) + " in 16-bit codes; render with --linear16 (16-bit linear PNG) or to .exr");
}

// Wraps the pixels without copying; the Image must outlive the buffer.
OIIO::ImageBuf wrapImage(const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
    return OIIO::ImageBuf(spec, const_cast<float*>(image.pixels.data()));
}

// Per pixel, the largest difference of the compared channels, in 16-bit codes.
struct PixelErrors {
    int width = 0;
    int height = 0;
    int channels = 0;
    bool wholeCodes = false;
    std::vector<double> codes;
};

PixelErrors pixelErrors(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const std::string& what) {
    const OIIO::ImageSpec& sa = a.spec();
    const OIIO::ImageSpec& sb = b.spec();
    if (sa.width != sb.width || sa.height != sb.height)
        throw Error(what + ": the images differ in size (" + std::to_string(sa.width) + "x" +
                    std::to_string(sa.height) + " and " + std::to_string(sb.width) + "x" +
                    std::to_string(sb.height) + ")");
    PixelErrors errors;
    errors.width = sa.width;
    errors.height = sa.height;
    errors.channels = std::min({3, sa.nchannels, sb.nchannels});
    if (errors.channels <= 0) throw Error(what + ": an image has no channels");

    OIIO::ROI roi(0, sa.width, 0, sa.height, 0, 1, 0, errors.channels);
    size_t values = static_cast<size_t>(sa.width) * sa.height * errors.channels;
    std::vector<double> pa(values), pb(values);
    if (!a.get_pixels(roi, OIIO::TypeDesc::DOUBLE, pa.data()) ||
        !b.get_pixels(roi, OIIO::TypeDesc::DOUBLE, pb.data()))
        throw Error(what + ": cannot read the pixels");
    // Two 16-bit integer images differ by whole codes; rounding removes the conversion's dust.
    bool wholeCodes = sa.format == OIIO::TypeDesc::UINT16 && sb.format == OIIO::TypeDesc::UINT16;
    errors.wholeCodes = wholeCodes;
    errors.codes.assign(static_cast<size_t>(sa.width) * sa.height, 0.0);
    for (size_t pixel = 0; pixel < errors.codes.size(); ++pixel) {
        double worst = 0.0;
        for (int c = 0; c < errors.channels; ++c) {
            size_t i = pixel * errors.channels + c;
            double difference = std::abs(pa[i] - pb[i]) * kCodesPerUnit;
            if (std::isnan(difference)) difference = std::numeric_limits<double>::infinity();
            worst = std::max(worst, wholeCodes ? std::round(difference) : difference);
        }
        errors.codes[pixel] = worst;
    }
    return errors;
}

ImageComparison compareBuffers(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, double thresholdCodes,
                               const std::string& what) {
    PixelErrors errors = pixelErrors(a, b, what);
    ImageComparison result;
    result.width = errors.width;
    result.height = errors.height;
    result.channels = errors.channels;
    result.wholeCodes = errors.wholeCodes;
    result.thresholdCodes = thresholdCodes;

    OIIO::ROI roi(0, errors.width, 0, errors.height, 0, 1, 0, errors.channels);
    float threshold = static_cast<float>(thresholdCodes / kCodesPerUnit);
    OIIO::ImageBufAlgo::CompareResults stats = OIIO::ImageBufAlgo::compare(a, b, threshold, threshold, roi);
    // stats.error only says that some value exceeded failthresh; real errors land on the buffers.
    if (a.has_error() || b.has_error()) throw Error(what + ": OpenImageIO: " + a.geterror() + b.geterror());
    result.meanError = stats.meanerror;
    result.maxError = stats.maxerror;
    result.rmse = stats.rms_error;
    result.psnr = stats.rms_error > 0.0 ? 20.0 * std::log10(1.0 / stats.rms_error)
                                        : std::numeric_limits<double>::infinity();
    result.maxX = stats.maxx;
    result.maxY = stats.maxy;

    result.pixelCount = errors.codes.size();
    for (double codes : errors.codes) {
        if (codes > thresholdCodes) ++result.pixelsOverThreshold;
        int bucket = codes == 0.0 ? 0 : codes <= 1.0 ? 1 : codes <= 2.0 ? 2 : 3;
        ++result.pixelsByCodes[bucket];
    }
    std::vector<double> sorted = errors.codes;
    auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    result.medianPixelCodes = *middle;
    return result;
}

constexpr float kEqualGreyScale = 0.35f;  // equal pixels: image A's brightness, dimmed to at most this

// Per pixel, the largest difference of the compared channels after both images are quantised
// to 16-bit codes as our PNGs and POV-Ray's are: a float render that rounds to its reference's
// codes is equal here (grey), not 1 code off (blue) everywhere. NaN is the worst error.
std::vector<double> quantisedCodeErrors(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const PixelErrors& errors) {
    OIIO::ROI roi(0, errors.width, 0, errors.height, 0, 1, 0, errors.channels);
    std::vector<float> pa(errors.codes.size() * errors.channels), pb(pa.size());
    if (!a.get_pixels(roi, OIIO::TypeDesc::FLOAT, pa.data()) || !b.get_pixels(roi, OIIO::TypeDesc::FLOAT, pb.data()))
        throw Error("heat map: cannot read the pixels");
    std::vector<double> codes(errors.codes.size(), 0.0);
    for (size_t pixel = 0; pixel < codes.size(); ++pixel)
        for (int c = 0; c < errors.channels; ++c) {
            size_t i = pixel * errors.channels + c;
            double difference = std::isnan(pa[i]) || std::isnan(pb[i])
                                    ? std::numeric_limits<double>::infinity()
                                    : std::abs(int(encodeLinear16(pa[i])) - int(encodeLinear16(pb[i])));
            codes[pixel] = std::max(codes[pixel], difference);
        }
    return codes;
}

void writeHeatMapOf(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const std::string& heatMapPath) {
    PixelErrors errors = pixelErrors(a, b, heatMapPath);
    std::vector<double> codes = quantisedCodeErrors(a, b, errors);
    OIIO::ROI roi(0, errors.width, 0, errors.height, 0, 1, 0, errors.channels);
    std::vector<float> context(errors.codes.size() * errors.channels);
    a.get_pixels(roi, OIIO::TypeDesc::FLOAT, context.data());

    OIIO::ImageSpec spec(errors.width, errors.height, 3, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf heat(spec);
    std::vector<float> rgb(codes.size() * 3);
    for (size_t pixel = 0; pixel < codes.size(); ++pixel) {
        float* out = &rgb[pixel * 3];
        if (codes[pixel] == 0.0) {
            // Dim grey from image A, so silhouettes and shadows can be recognised.
            float sum = 0.0f;
            for (int c = 0; c < errors.channels; ++c) sum += context[pixel * errors.channels + c];
            float grey = kEqualGreyScale * std::sqrt(std::clamp(sum / errors.channels, 0.0f, 1.0f));
            out[0] = out[1] = out[2] = grey;
            continue;
        }
        for (const HeatMapBand& band : errorHeatMapBands()) {
            if (codes[pixel] <= band.maxCodes) {
                std::copy(band.rgb, band.rgb + 3, out);
                break;
            }
        }
    }
    heat.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb.data());
    if (!heat.write(heatMapPath)) {
        std::string message = heat.geterror();
        std::replace(message.begin(), message.end(), '\n', ' ');
        throw Error(heatMapPath + ": cannot write the heat map: " + message);
    }
}

double meanValue(const Image& image) {
    int channels = std::min(image.channels, 3);
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < image.pixels.size(); i += image.channels)
        for (int c = 0; c < channels; ++c, ++count) sum += image.pixels[i + c];
    return count > 0 ? sum / count : 0.0;
}

}  // namespace

ImageComparison compareImages(const std::string& pathA, const std::string& pathB, double thresholdCodes) {
    OIIO::ImageBuf a = readBuffer(pathA), b = readBuffer(pathB);
    checkComparable(a, b, pathA, pathB);
    return compareBuffers(a, b, thresholdCodes, pathA + " vs " + pathB);
}

ImageComparison compareImages(const Image& a, const Image& b, double thresholdCodes) {
    return compareBuffers(wrapImage(a), wrapImage(b), thresholdCodes, "image comparison");
}

void writeErrorHeatMap(const std::string& pathA, const std::string& pathB, const std::string& heatMapPath) {
    OIIO::ImageBuf a = readBuffer(pathA), b = readBuffer(pathB);
    checkComparable(a, b, pathA, pathB);
    writeHeatMapOf(a, b, heatMapPath);
}

void writeErrorHeatMap(const Image& a, const Image& b, const std::string& heatMapPath) {
    writeHeatMapOf(wrapImage(a), wrapImage(b), heatMapPath);
}

const std::vector<HeatMapBand>& errorHeatMapBands() {
    // Discrete bands: one glance tells rounding (1-2 codes) from real differences.
    static const std::vector<HeatMapBand> bands = {
        {1.0, {0.10f, 0.35f, 1.00f}, "blue", "1 code"},
        {2.0, {0.00f, 0.85f, 0.35f}, "green", "2 codes"},
        {15.0, {1.00f, 0.90f, 0.00f}, "yellow", "3-15 codes"},
        {255.0, {1.00f, 0.50f, 0.00f}, "orange", "16-255 codes"},
        {std::numeric_limits<double>::infinity(), {1.00f, 0.00f, 0.00f}, "red", "256 codes or more, or NaN"},
    };
    return bands;
}

std::string errorHeatMapLegend() {
    std::string legend = "grey = equal in 16-bit codes (image A, dimmed)";
    for (const HeatMapBand& band : errorHeatMapBands()) legend += ", " + band.colourName + " = " + band.meaning;
    return legend;
}

ImageAgreement agreementWith(const ImageComparison& comparison, const std::string& committedPath, double relativeRmsTolerance) {
    ImageAgreement result;
    result.identical = comparison.pixelsOverThreshold == 0;
    result.relativeRms = result.identical ? 0.0 : comparison.rmse / meanValue(readImage(committedPath));
    result.agrees = result.identical || result.relativeRms <= relativeRmsTolerance;
    return result;
}

}  // namespace rtlab
