#include "framework/verification/statistical_comparison.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

namespace rtlab {
namespace {

// 1 - (1 - alpha)^(1/tests): each of `tests` independent tests at this level keeps the
// family's at alpha.
double sidakLevel(double alpha, uint64_t tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / double(tests)); }

// P(|Z| >= |z|) for a standard normal Z.
double twoSidedP(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

// A z statistic whose error scale may be zero: equal values then pass, others fail.
double zScore(double difference, double variance) {
    if (variance > 0.0) return difference / std::sqrt(variance);
    return difference == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

// Sums over rectangles of a per-pixel quantity in constant time (a summed-area table).
class BoxSums {
public:
    BoxSums(int width, int height, const std::function<double(int, int)>& value)
        : width_(width), height_(height), sums_(static_cast<size_t>(width + 1) * (height + 1), 0.0) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                sums_[index(x + 1, y + 1)] = value(x, y) + sums_[index(x, y + 1)] + sums_[index(x + 1, y)] - sums_[index(x, y)];
    }
    // The sum over the square of half-size r around (x, y), clipped at the border, and its pixel count.
    std::pair<double, int> around(int x, int y, int r) const {
        int x0 = std::max(0, x - r), y0 = std::max(0, y - r);
        int x1 = std::min(width_, x + r + 1), y1 = std::min(height_, y + r + 1);
        double sum = sums_[index(x1, y1)] - sums_[index(x0, y1)] - sums_[index(x1, y0)] + sums_[index(x0, y0)];
        return {sum, (x1 - x0) * (y1 - y0)};
    }

private:
    size_t index(int x, int y) const { return static_cast<size_t>(y) * (width_ + 1) + x; }
    int width_, height_;
    std::vector<double> sums_;
};

// The variance each pixel value is tested with. A pixel's K samples may all miss a light that
// a sample reaches rarely (a hemisphere estimator far from a small light): its sample variance
// is then 0 and says nothing. Its neighbours, which see the same light the same way, do
// better together: the variance is the largest of the value's own, the mean over the smallest
// square around it (half-size 1, 2, 4, 8 or 16 pixels) in which kPooledPixels pixels have a
// variance (or the largest square), and the floor floorDeviation^2.
constexpr int kPooledPixels = 9;
constexpr int kPoolHalfSizes[] = {1, 2, 4, 8, 16};

std::vector<double> testVariances(const ReplicateStatistics& ours, double floorDeviation) {
    const int w = ours.width(), h = ours.height(), channels = ours.channels();
    auto at = [&](int x, int y, int c) { return (static_cast<size_t>(y) * w + x) * channels + c; };
    std::vector<double> variance(static_cast<size_t>(w) * h * channels);
    for (int c = 0; c < channels; ++c) {
        BoxSums sums(w, h, [&](int x, int y) { return ours.variance(at(x, y, c)); });
        BoxSums varying(w, h, [&](int x, int y) { return ours.variance(at(x, y, c)) > 0.0 ? 1.0 : 0.0; });
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double pooled = 0.0;
                for (int r : kPoolHalfSizes) {
                    auto [sum, n] = sums.around(x, y, r);
                    pooled = sum / n;
                    if (varying.around(x, y, r).first >= kPooledPixels) break;
                }
                variance[at(x, y, c)] = std::max({ours.variance(at(x, y, c)), pooled, floorDeviation * floorDeviation});
            }
    }
    return variance;
}

// The mean of the reference over the pixels compared, all channels: the scale of the floor.
double referenceScale(const Image& reference, int channels, const std::function<bool(int, int)>& compared) {
    double sum = 0.0;
    uint64_t n = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            for (int c = 0; c < channels && compared(x, y); ++c)
                if (std::isfinite(reference.at(x, y, c))) {
                    sum += reference.at(x, y, c);
                    ++n;
                }
    return n ? sum / double(n) : 0.0;
}

// What both families of tests read: our means, the variances to test them with (testVariances),
// the reference, and which pixels are compared.
struct TestInputs {
    const ReplicateStatistics& ours;
    const Image& reference;
    std::vector<double> variance;
    std::function<bool(int, int)> compared;

    size_t value(int x, int y, int c) const { return (static_cast<size_t>(y) * ours.width() + x) * ours.channels() + c; }
    double standardErrorSquared(size_t v) const { return variance[v] / ours.replicates(); }
};

RegionResult regionTest(const TestInputs& in, RegionResult r, const StatisticalTolerances& tolerances, double level) {
    double sumOurs = 0.0, sumReference = 0.0, sumSquaredErrors = 0.0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            if (!in.compared(x, y)) continue;
            ++r.pixels;
            size_t v = in.value(x, y, r.channel);
            sumOurs += in.ours.mean(v);
            sumSquaredErrors += in.standardErrorSquared(v);  // pixels draw from independent streams
            sumReference += in.reference.at(x, y, r.channel);
        }
    double n = std::max(r.pixels, 1);
    r.ours = sumOurs / n;
    r.reference = sumReference / n;
    r.standardError = std::sqrt(sumSquaredErrors) / n;
    double referenceError = tolerances.referenceRegionError * r.reference;
    r.z = zScore(r.ours - r.reference, r.standardError * r.standardError + referenceError * referenceError);
    r.passes = twoSidedP(r.z) >= level;  // NaN fails
    return r;
}

void pixelTests(const TestInputs& in, const StatisticalTolerances& tolerances, StatisticalComparison& result) {
    const int w = in.ours.width(), h = in.ours.height(), channels = in.ours.channels();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) result.pixelsLeftOut += !in.compared(x, y);
    result.pixelValues = (uint64_t(w) * h - result.pixelsLeftOut) * channels;
    result.pixelLevel = sidakLevel(tolerances.alpha, std::max<uint64_t>(result.pixelValues, 1));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels && in.compared(x, y); ++c) {
                size_t v = in.value(x, y, c);
                double b = in.reference.at(x, y, c);
                double referenceError = tolerances.referencePixelError * b;
                double z = std::isfinite(b)
                               ? zScore(in.ours.mean(v) - b, in.standardErrorSquared(v) + referenceError * referenceError)
                               : std::numeric_limits<double>::infinity();
                if (!(twoSidedP(z) >= result.pixelLevel)) ++result.pixelFailures;  // NaN fails
                if (!(std::abs(z) <= std::abs(result.worstPixelZ))) {
                    result.worstPixelZ = z;
                    result.worstX = x;
                    result.worstY = y;
                }
            }
}

}  // namespace

int StatisticalComparison::regionFailures() const {
    return static_cast<int>(std::count_if(regions.begin(), regions.end(), [](const RegionResult& r) { return !r.passes; }));
}

StatisticalComparison compareStatistically(const ReplicateStatistics& ours, const Image& reference,
                                           const std::vector<uint8_t>& leftOut, const StatisticalTolerances& tolerances) {
    const int w = ours.width(), h = ours.height(), channels = ours.channels();
    if (ours.replicates() < 2) throw Error("statistical comparison: fewer than two replicates");
    if (reference.width != w || reference.height != h || reference.channels < channels)
        throw Error("statistical comparison: the reference is " + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + " with " + std::to_string(reference.channels) +
                    " channels, our render " + std::to_string(w) + "x" + std::to_string(h) + " with " +
                    std::to_string(channels));
    if (!leftOut.empty() && leftOut.size() != size_t(w) * h)
        throw Error("statistical comparison: " + std::to_string(leftOut.size()) + " pixel flags for " +
                    std::to_string(w) + "x" + std::to_string(h) + " pixels");
    std::function<bool(int, int)> compared = [&](int x, int y) { return leftOut.empty() || !leftOut[size_t(y) * w + x]; };
    double floor = tolerances.sampleDeviationFloor * referenceScale(reference, channels, compared);
    TestInputs in{ours, reference, testVariances(ours, floor), compared};

    StatisticalComparison result;
    result.replicates = ours.replicates();
    result.tolerances = tolerances;
    int columns = std::min(tolerances.regionsX, w), rows = std::min(tolerances.regionsY, h);
    result.regionLevel = sidakLevel(tolerances.alpha, uint64_t(columns) * rows * channels);
    for (int ry = 0; ry < rows; ++ry)
        for (int rx = 0; rx < columns; ++rx)
            for (int c = 0; c < channels; ++c) {
                RegionResult r;
                r.x0 = rx * w / columns;
                r.x1 = (rx + 1) * w / columns;
                r.y0 = ry * h / rows;
                r.y1 = (ry + 1) * h / rows;
                r.channel = c;
                result.regions.push_back(regionTest(in, r, tolerances, result.regionLevel));
            }
    pixelTests(in, tolerances, result);
    return result;
}

}  // namespace rtlab
