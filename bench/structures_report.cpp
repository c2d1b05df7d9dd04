#include "bench/structures_report.h"

#include "bench/report.h"
#include "bench/svg_plot.h"

#include <algorithm>

namespace rtlab::bench {

void writeStructuresSvg(const std::string& path, const std::vector<ThroughputRecord>& records) {
    Plot plot{"Build time against the time to trace 10^6 primary rays (one thread)", "build ms", "trace ms per 10^6 rays", true, true, {}};
    const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
    std::vector<std::string> scenes;
    for (const ThroughputRecord& r : records)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    bool comparable = false;
    for (size_t s = 0; s < scenes.size(); ++s) {
        // Markers only: the structures are not an ordered sequence, so no line joins them.
        PlotSeries series{scenes[s], colours[s % 6], {}, false, true, false};
        for (const ThroughputRecord& r : records) {
            if (r.scene != scenes[s] || r.system.starts_with("embree:high") || primaryRow(records, r.scene, r.system) != &r) continue;
            if (r.mraysPerSecond <= 0) continue;
            // "rtlab:kdtree" reads "kdtree" on the chart; Embree keeps its prefix.
            std::string label = r.system.starts_with("rtlab:") ? r.system.substr(6) : r.system;
            series.points.push_back({r.buildMs, 1e3 / r.mraysPerSecond, label});
        }
        comparable = comparable || series.points.size() >= 2;
        plot.series.push_back(series);
    }
    if (comparable) writeSvg(path, plot);
}

}  // namespace rtlab::bench
