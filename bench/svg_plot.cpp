#include "bench/svg_plot.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace rtlab::bench {

namespace {

constexpr double kWidth = 720, kHeight = 480;
constexpr double kLeft = 80, kRight = 190, kTop = 40, kBottom = 60;  // margins; the legend sits on the right

struct Axis {
    bool log;
    double lo, hi;      // data range (log10 of it on a log axis)
    double from, to;    // pixel range

    double value(double v) const { return log ? std::log10(v) : v; }
    double pixel(double v) const { return from + (value(v) - lo) / (hi - lo) * (to - from); }
};

bool drawable(double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); }

Axis makeAxis(const Plot& plot, bool isX, double from, double to) {
    bool log = isX ? plot.logX : plot.logY;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const PlotSeries& s : plot.series)
        for (const PlotPoint& p : s.points) {
            double v = isX ? p.x : p.y;
            if (!drawable(p.x, plot.logX) || !drawable(p.y, plot.logY)) continue;
            lo = std::min(lo, log ? std::log10(v) : v);
            hi = std::max(hi, log ? std::log10(v) : v);
        }
    if (!(lo <= hi)) lo = 0, hi = 1;
    if (log) {
        lo = std::floor(lo);
        hi = std::max(std::ceil(hi), lo + 1);
    } else {
        double pad = hi > lo ? 0.05 * (hi - lo) : std::max(std::fabs(lo) * 0.1, 1.0);
        lo -= pad;
        hi += pad;
        if (lo < 0 && lo + pad >= 0) lo = 0;  // keep non-negative data on a non-negative axis
    }
    return Axis{log, lo, hi, from, to};
}

// Tick positions in data units: decades (and 2, 5 between few decades) on a log axis, a 1-2-5
// step on a linear one.
std::vector<double> ticks(const Axis& axis) {
    std::vector<double> out;
    if (axis.log) {
        bool fine = axis.hi - axis.lo <= 3;
        for (int e = static_cast<int>(axis.lo); e <= static_cast<int>(axis.hi); ++e)
            for (double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
                double v = m * std::pow(10.0, e);
                if (std::log10(v) <= axis.hi + 1e-9) out.push_back(v);
            }
        return out;
    }
    double span = axis.hi - axis.lo, raw = span / 6;
    double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude * (raw / magnitude < 2 ? 2 : raw / magnitude < 5 ? 5 : 10);
    for (double v = std::ceil(axis.lo / step) * step; v <= axis.hi + 1e-9 * span; v += step) out.push_back(v);
    return out;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

}  // namespace

void writeSvg(const std::string& path, const Plot& plot) {
    Axis x = makeAxis(plot, true, kLeft, kWidth - kRight);
    Axis y = makeAxis(plot, false, kHeight - kBottom, kTop);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << kWidth / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escape(plot.title)
        << "</text>\n";
    // Grid, ticks and tick labels.
    for (double v : ticks(x)) {
        double px = x.pixel(v);
        svg << "<line x1=\"" << px << "\" y1=\"" << kTop << "\" x2=\"" << px << "\" y2=\"" << kHeight - kBottom
            << "\" stroke=\"#e4e4e4\"/>\n<text x=\"" << px << "\" y=\"" << kHeight - kBottom + 16
            << "\" text-anchor=\"middle\">" << number(v) << "</text>\n";
    }
    for (double v : ticks(y)) {
        double py = y.pixel(v);
        svg << "<line x1=\"" << kLeft << "\" y1=\"" << py << "\" x2=\"" << kWidth - kRight << "\" y2=\"" << py
            << "\" stroke=\"#e4e4e4\"/>\n<text x=\"" << kLeft - 6 << "\" y=\"" << py + 4
            << "\" text-anchor=\"end\">" << number(v) << "</text>\n";
    }
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << kWidth - kRight - kLeft << "\" height=\""
        << kHeight - kBottom - kTop << "\" fill=\"none\" stroke=\"black\"/>\n";
    svg << "<text x=\"" << (kLeft + kWidth - kRight) / 2 << "\" y=\"" << kHeight - 18 << "\" text-anchor=\"middle\">"
        << escape(plot.xLabel) << (plot.logX ? " (log)" : "") << "</text>\n";
    svg << "<text transform=\"translate(18," << (kTop + kHeight - kBottom) / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << escape(plot.yLabel) << (plot.logY ? " (log)" : "")
        << "</text>\n";

    double legendY = kTop + 10;
    for (const PlotSeries& s : plot.series) {
        std::vector<const PlotPoint*> points;
        for (const PlotPoint& p : s.points)
            if (drawable(p.x, plot.logX) && drawable(p.y, plot.logY)) points.push_back(&p);
        if (s.line && points.size() > 1) {
            svg << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\""
                << (s.dashed ? " stroke-dasharray=\"5,4\"" : "") << " points=\"";
            for (const PlotPoint* p : points) svg << x.pixel(p->x) << "," << y.pixel(p->y) << " ";
            svg << "\"/>\n";
        }
        for (const PlotPoint* p : points) {
            if (s.markers)
                svg << "<circle cx=\"" << x.pixel(p->x) << "\" cy=\"" << y.pixel(p->y) << "\" r=\"3.5\" fill=\""
                    << s.colour << "\"><title>" << escape(s.name + " " + p->label) << " (" << number(p->x) << ", "
                    << number(p->y) << ")</title></circle>\n";
            if (!p->label.empty())
                svg << "<text x=\"" << x.pixel(p->x) + 5 << "\" y=\"" << y.pixel(p->y) - 5
                    << "\" font-size=\"10\" fill=\"" << s.colour << "\">" << escape(p->label) << "</text>\n";
        }
        double lx = kWidth - kRight + 14;
        svg << "<line x1=\"" << lx << "\" y1=\"" << legendY << "\" x2=\"" << lx + 22 << "\" y2=\"" << legendY
            << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"5,4\"" : "")
            << "/>\n<text x=\"" << lx + 28 << "\" y=\"" << legendY + 4 << "\">" << escape(s.name) << "</text>\n";
        legendY += 18;
    }
    svg << "</svg>\n";

    std::ofstream out(path);
    if (!out || !(out << svg.str()) || !out.flush()) throw Error(path + ": cannot write the SVG file");
}

}  // namespace rtlab::bench
