#include "framework/render/statistical_comparison.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

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

}  // namespace

int StatisticalComparison::regionFailures() const {
    return static_cast<int>(std::count_if(regions.begin(), regions.end(), [](const RegionResult& r) { return !r.passes; }));
}

StatisticalComparison compareStatistically(const ReplicateStatistics& ours, const Image& reference,
                                           const std::vector<uint8_t>& leftOut, const StatisticalTolerances& tolerances) {
    if (ours.replicates() < 2) throw Error("statistical comparison: fewer than two replicates");
    if (reference.width != ours.width() || reference.height != ours.height() || reference.channels < ours.channels())
        throw Error("statistical comparison: the reference is " + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + " with " + std::to_string(reference.channels) +
                    " channels, our render " + std::to_string(ours.width()) + "x" + std::to_string(ours.height()) +
                    " with " + std::to_string(ours.channels()));
    if (!leftOut.empty() && leftOut.size() != size_t(ours.width()) * ours.height())
        throw Error("statistical comparison: " + std::to_string(leftOut.size()) + " pixel flags for " +
                    std::to_string(ours.width()) + "x" + std::to_string(ours.height()) + " pixels");
    auto compared = [&](int x, int y) { return leftOut.empty() || !leftOut[size_t(y) * ours.width() + x]; };
    StatisticalComparison result;
    result.replicates = ours.replicates();
    result.tolerances = tolerances;
    const int channels = ours.channels();
    const double k = ours.replicates();
    auto ourValue = [&](int x, int y, int c) { return (static_cast<size_t>(y) * ours.width() + x) * channels + c; };

    int columns = std::min(tolerances.regionsX, ours.width()), rows = std::min(tolerances.regionsY, ours.height());
    result.regionLevel = sidakLevel(tolerances.alpha, uint64_t(columns) * rows * channels);
    for (int ry = 0; ry < rows; ++ry)
        for (int rx = 0; rx < columns; ++rx)
            for (int c = 0; c < channels; ++c) {
                RegionResult r;
                r.x0 = rx * ours.width() / columns;
                r.x1 = (rx + 1) * ours.width() / columns;
                r.y0 = ry * ours.height() / rows;
                r.y1 = (ry + 1) * ours.height() / rows;
                r.channel = c;
                double sumOurs = 0.0, sumReference = 0.0, sumVariance = 0.0;
                for (int y = r.y0; y < r.y1; ++y)
                    for (int x = r.x0; x < r.x1; ++x) {
                        if (!compared(x, y)) continue;
                        ++r.pixels;
                        sumOurs += ours.mean(ourValue(x, y, c));
                        sumVariance += ours.variance(ourValue(x, y, c)) / k;
                        sumReference += reference.at(x, y, c);
                    }
                double n = std::max(r.pixels, 1);
                r.ours = sumOurs / n;
                r.reference = sumReference / n;
                r.standardError = std::sqrt(sumVariance) / n;
                double referenceError = tolerances.referenceRegionError * r.reference;
                r.z = zScore(r.ours - r.reference, r.standardError * r.standardError + referenceError * referenceError);
                r.passes = twoSidedP(r.z) >= result.regionLevel;  // NaN fails
                result.regions.push_back(r);
            }

    for (int y = 0; y < ours.height(); ++y)
        for (int x = 0; x < ours.width(); ++x) result.pixelsLeftOut += !compared(x, y);
    result.pixelValues = (uint64_t(ours.width()) * ours.height() - result.pixelsLeftOut) * channels;
    result.pixelLevel = sidakLevel(tolerances.alpha, std::max<uint64_t>(result.pixelValues, 1));
    for (int y = 0; y < ours.height(); ++y)
        for (int x = 0; x < ours.width(); ++x)
            for (int c = 0; c < channels; ++c) {
                if (!compared(x, y)) continue;
                size_t v = ourValue(x, y, c);
                double b = reference.at(x, y, c);
                double referenceError = tolerances.referencePixelError * b;
                double z = std::isfinite(b) ? zScore(ours.mean(v) - b, ours.variance(v) / k + referenceError * referenceError)
                                            : std::numeric_limits<double>::infinity();
                if (!(twoSidedP(z) >= result.pixelLevel)) ++result.pixelFailures;  // NaN fails
                if (!(std::abs(z) <= std::abs(result.worstPixelZ))) {
                    result.worstPixelZ = z;
                    result.worstX = x;
                    result.worstY = y;
                }
            }
    return result;
}

}  // namespace rtlab
