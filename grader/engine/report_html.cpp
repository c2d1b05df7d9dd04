// The HTML report: a summary table and, per test, its messages (failing rays with expected
// and actual answers, SAH costs, work per ray) and for image tests the render, the POV-Ray
// reference and the difference heat map side by side, with the heat map's legend once under
// them; for a failing test, its "open in viewer" links (viewer/report_viewers.h writes the
// pages). Self-contained: images are copied next to index.html, viewers are in viewer/.
#include "framework/core/error.h"
#include "framework/verification/image_compare.h"
#include "grader/engine/grading_report.h"
#include "grader/engine/markup_escape.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

std::string anchor(const std::string& name) {
    std::string a;
    for (char c : name) a += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
    return a;
}

const char* kStyle = R"(body{font-family:sans-serif;margin:2em;max-width:1400px}
table{border-collapse:collapse}td,th{padding:2px 10px;text-align:left;border-bottom:1px solid #ddd}
.passed{color:#176b1f}.failed{color:#b00020}.not-started{color:#9a6700}
pre{background:#f6f6f6;padding:8px;white-space:pre-wrap;font-size:90%}
.swatch{margin-right:14px;white-space:nowrap}.swatch span{display:inline-block;width:1em;height:1em;margin-right:4px;vertical-align:middle;border:1px solid #888}
.images{display:flex;gap:12px;flex-wrap:wrap}.images figure{margin:0}.images img{max-width:440px;image-rendering:pixelated}
)";

// The heat map's colours as swatches with the error each means (framework/verification/image_compare.h).
std::string heatMapLegend() {
    auto swatch = [](const float rgb[3], const std::string& meaning) {
        char colour[8];
        std::snprintf(colour, sizeof colour, "#%02x%02x%02x", int(std::lround(rgb[0] * 255)), int(std::lround(rgb[1] * 255)),
                      int(std::lround(rgb[2] * 255)));
        return std::string("<span class=\"swatch\"><span style=\"background:") + colour + "\"></span>" + escapeMarkup(meaning) +
               "</span>";
    };
    const float grey[3] = {0.25f, 0.25f, 0.25f};
    std::string legend = "<p class=\"legend\">Difference, after both images are quantised to 16-bit codes: " +
                         swatch(grey, "equal (your render, dimmed)");
    for (const HeatMapBand& band : errorHeatMapBands()) legend += swatch(band.rgb, band.colourName + ": " + band.meaning);
    return legend + "</p>\n";
}

}  // namespace

void writeHtmlReport(const GradingReport& untrusted, const std::string& directory, const ReportLinks& viewerLinks) {
    const GradingReport report = displaySafe(untrusted);
    fs::create_directories(fs::path(directory) / "images");
    std::ostringstream html;
    char total[128];
    std::snprintf(total, sizeof total, "%.2f of %.2f points", report.score(), report.maxScore());
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>rtlab grading report</title><style>" << kStyle
         << "</style></head><body>\n<h1>rtlab grading report</h1>\n<p>" << escapeMarkup(report.implementation) << ", seed "
         << report.seed << ": <b>" << total << "</b> in " << report.seconds << " s.</p>\n<table><tr><th>test</th><th>status</th>"
         << "<th>points</th><th>reason</th></tr>\n";
    for (const TestResult& t : report.tests) {
        std::string status = testStatusName(t.status);
        std::snprintf(total, sizeof total, "%.2f/%.2f", t.score, t.maxScore);
        html << "<tr><td><a href=\"#" << anchor(t.name) << "\">" << escapeMarkup(t.name) << "</a></td><td class=\"" << anchor(status)
             << "\">" << status << "</td><td>" << total << "</td><td>" << escapeMarkup(t.reason) << "</td></tr>\n";
    }
    html << "</table>\n";
    int imageNumber = 0;
    for (size_t i = 0; i < report.tests.size(); ++i) {
        const TestResult& t = report.tests[i];
        std::string status = testStatusName(t.status);
        html << "<h2 id=\"" << anchor(t.name) << "\">" << escapeMarkup(t.name) << " <span class=\"" << anchor(status) << "\">" << status
             << "</span></h2>\n";
        // The reason is in the table above; here the lines behind it, so it is shown once.
        std::string output;
        for (const std::string& line : t.details) output += (output.empty() ? "" : "\n") + line;
        if (!output.empty()) html << "<pre>" << escapeMarkup(output) << "</pre>\n";
        // Keyed by the name as graded: the links were made from the report before displaySafe.
        if (auto links = viewerLinks.find(untrusted.tests[i].name); links != viewerLinks.end()) {
            html << "<ul class=\"viewer-links\">\n";
            for (const ReportLink& link : links->second) {
                if (link.href.empty()) html << "<li>" << escapeMarkup(link.label) << "</li>\n";
                else html << "<li><a href=\"" << escapeMarkup(link.href) << "\">open in viewer</a>: " << escapeMarkup(link.label) << "</li>\n";
            }
            html << "</ul>\n";
        }
        if (t.images.empty()) continue;
        html << "<div class=\"images\">\n";
        for (const ReportImage& image : t.images) {
            std::string file = "images/" + std::to_string(++imageNumber) + "-" + fs::path(image.path).filename().string();
            std::error_code error;
            fs::copy_file(image.path, fs::path(directory) / file, fs::copy_options::overwrite_existing, error);
            html << "<figure><img src=\"" << escapeMarkup(file) << "\" alt=\"" << escapeMarkup(image.label) << "\"><figcaption>"
                 << escapeMarkup(image.label) << "</figcaption></figure>\n";
        }
        html << "</div>\n";
        bool heatMap = false;
        for (const ReportImage& image : t.images) heatMap = heatMap || image.path.ends_with(kHeatMapFileSuffix);
        if (heatMap) html << heatMapLegend();
    }
    if (!report.studentOutput.empty())
        html << "<h2>What your code printed</h2>\n<pre>" << escapeMarkup(report.studentOutput) << "</pre>\n";
    if (!report.isolation.empty()) html << "<h2>Isolation</h2>\n<p>" << escapeMarkup(report.isolation) << "</p>\n";
    html << "</body></html>\n";
    std::string path = (fs::path(directory) / "index.html").string();
    std::ofstream out(path, std::ios::binary);
    out << html.str();
    if (!out) throw Error(path + ": cannot write the HTML report");
}

}  // namespace rtlab::grader
