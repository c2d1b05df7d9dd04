// A small SVG chart writer for the benchmark's plots: scatter and line series on linear or
// logarithmic axes, with ticks, axis titles, point labels and a legend. Enough for a few
// dozen points; no plotting library needed.
#pragma once

#include <string>
#include <vector>

namespace rtlab::bench {

struct PlotPoint {
    double x;
    double y;
    std::string label;  // drawn next to the point when not empty
};

struct PlotSeries {
    std::string name;
    std::string colour = "#1f77b4";
    std::vector<PlotPoint> points;
    bool line = true;     // connect the points in order
    bool markers = true;  // draw a dot at each point
    bool dashed = false;
};

struct Plot {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    bool logX = false;
    bool logY = false;
    std::vector<PlotSeries> series;
};

// Throws rtlab::Error when the file cannot be written. Points that cannot be drawn (non-finite,
// or not positive on a log axis) are left out.
void writeSvg(const std::string& path, const Plot& plot);

}  // namespace rtlab::bench
