#include "cli/statistical_report.h"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace rtlab::cli {
namespace {

double relative(double ours, double reference) { return reference != 0.0 ? ours / reference - 1.0 : ours - reference; }

const RegionResult* worstRegion(const StatisticalComparison& c) {
    const RegionResult* worst = nullptr;
    for (const RegionResult& r : c.regions)
        if (!worst || !(std::abs(r.z) <= std::abs(worst->z))) worst = &r;
    return worst;
}

}  // namespace

std::string statisticalSummary(const StatisticalComparison& c) {
    std::ostringstream out;
    out << std::setprecision(2);
    out << "regions " << c.regions.size() - c.regionFailures() << "/" << c.regions.size() << " agree";
    if (const RegionResult* worst = worstRegion(c))
        out << " (worst z " << worst->z << ", rel " << relative(worst->ours, worst->reference) << ")";
    out << ", " << c.pixelsLeftOut << " edge pixels left out, pixel channels " << c.pixelFailures << " of " << c.pixelValues << " differ (" << 100.0 * c.pixelFailureShare()
        << " %, allowed " << 100.0 * c.tolerances.allowedPixelFailures << " %; worst z " << c.worstPixelZ << " at ("
        << c.worstX << ", " << c.worstY << ")), " << c.replicates << " replicates";
    return out.str();
}

void printRegionTable(std::ostream& out, const StatisticalComparison& c) {
    std::ios flags(nullptr);
    flags.copyfmt(out);
    out << "  region (pixels)        ch  compared  ours        s.e.       reference   rel. diff    z\n";
    for (const RegionResult& r : c.regions) {
        std::ostringstream box;
        box << "[" << r.x0 << "," << r.x1 << ")x[" << r.y0 << "," << r.y1 << ")";
        out << "  " << std::left << std::setw(22) << box.str() << " " << "RGBA"[r.channel % 4] << "   " << std::right
            << std::setw(8) << r.pixels << "  " << std::setprecision(6) << std::setw(10) << r.ours << "  " << std::setprecision(2) << std::setw(9)
            << r.standardError << "  " << std::setprecision(6) << std::setw(10) << r.reference << "  "
            << std::setprecision(2) << std::setw(9) << relative(r.ours, r.reference) << "  " << std::setw(6) << r.z
            << (r.passes ? "" : "  FAIL") << "\n";
    }
    out.copyfmt(flags);
}

}  // namespace rtlab::cli
