#include "viewer/report_viewers.h"

#include "framework/core/error.h"
#include "framework/core/untrusted_text.h"
#include "framework/oracle/oracle.h"

#include <cctype>

namespace rtlab::viewer {
namespace {

namespace fs = std::filesystem;

static_assert(int(RayAnswer::Kind::None) == int(grader::CaseAnswer::Kind::None) &&
                  int(RayAnswer::Kind::Closest) == int(grader::CaseAnswer::Kind::Closest) &&
                  int(RayAnswer::Kind::AnyHit) == int(grader::CaseAnswer::Kind::AnyHit),
              "the grader's answer kinds are the viewer's");

RayAnswer answerOf(const grader::CaseAnswer& a) {
    return RayAnswer{static_cast<RayAnswer::Kind>(a.kind), a.hit, a.t, a.prim};
}

// A folder name from a test name: letters, digits and '-' only, so the link needs no escaping.
std::string folderName(const std::string& testName, size_t k) {
    std::string name;
    for (char c : testName) name += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(static_cast<unsigned char>(c))) : '-';
    return name + "-" + std::to_string(k + 1);
}

// REPORT/viewer from an earlier report is removed when every folder in it is a viewer; anything
// else there is left alone, and then writing the new viewers refuses to overwrite it.
void removeOldViewers(const fs::path& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec))
        if (!entry.is_directory() || !fs::is_regular_file(entry.path() / kViewerMarker)) return;
    fs::remove_all(folder, ec);
}

// The failed image at its worst pixel: the three images, the camera's film and that pixel's
// camera ray with the oracle's hit (the student's renderer is not asked again).
void addImage(const grader::CaseImage& image, const Scene* scene, CaseView& view) {
    ImageSet set;
    set.render = image.render;
    set.reference = image.reference;
    set.difference = image.difference;
    set.legend = image.legend;
    set.width = image.width;
    set.height = image.height;
    if (scene && image.camera < scene->cameras.size() && image.width > 0 && image.height > 0) {
        set.film = scene->cameras[image.camera].film(image.width, image.height);
        if (image.worstPixel) {
            auto [x, y] = *image.worstPixel;
            set.selectedPixel = image.worstPixel;
            RayCase& r = view.rays.emplace_back();
            r.ray = set.film.through(x + 0.5, y + 0.5);
            r.label = "camera ray of the worst pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
            OracleHit hit = Oracle(*scene).closestHit(OracleRay::from(r.ray));
            r.expected = RayAnswer::closest(hit.hit ? hit.prim : kNoHit, float(hit.t));
        }
    }
    view.images = std::move(set);
}

}  // namespace

CaseView caseViewOf(const grader::FailedCase& failed) {
    CaseView view;
    view.title = failed.title;
    view.notes = failed.notes;
    view.scene = failed.scene.get();
    if (failed.structure) {
        view.acceleratorName = failed.accelerator;
        view.draw = failed.draw;
        view.structure = failed.structure;
        view.gridResolution = failed.gridResolution;
    }
    for (const grader::CaseRay& r : failed.rays) {
        RayCase c;
        c.ray = r.ray;
        c.label = r.label;
        c.student = answerOf(r.student);
        c.expected = answerOf(r.expected);
        c.studentTrace = r.studentTrace;
        c.expectedTrace = r.expectedTrace;
        c.expectedSource = r.expectedTrace ? "the exact oracle; steps in the exact order" : "the exact oracle";
        view.rays.push_back(std::move(c));
    }
    if (failed.cells) {
        DdaCells cells;
        cells.bounds = failed.cells->bounds;
        cells.resolution = failed.cells->resolution;
        cells.expected = failed.cells->expected;
        cells.student = failed.cells->student;
        view.dda = std::move(cells);
    }
    if (failed.image) addImage(*failed.image, view.scene, view);
    return view;
}

grader::ReportLinks writeReportViewers(const grader::GradingReport& report, const fs::path& reportDir) {
    const fs::path folder = reportDir / kReportViewerFolder;
    removeOldViewers(folder);
    grader::ReportLinks links;
    size_t pages = 0;
    for (const grader::TestResult& test : report.tests) {
        if (test.status != grader::TestStatus::Failed) continue;
        for (size_t k = 0; k < test.failedCases.size() && k < grader::kViewerCasesPerTest; ++k) {
            const grader::FailedCase& failed = test.failedCases[k];
            std::string name = folderName(test.name, k);
            std::string label = grader::escapeUntrusted(failed.title, grader::TextLayout::OneLine);
            if (pages >= kViewerPagesPerReport) {
                links[test.name].push_back({label + " (no viewer: the report's " + std::to_string(kViewerPagesPerReport) +
                                                " viewer pages went to the tests above)",
                                            ""});
                continue;
            }
            fs::create_directories(folder);
            try {
                writeCaseViewer(folder / name, caseViewOf(failed));
                links[test.name].push_back({label, std::string(kReportViewerFolder) + "/" + name + "/index.html"});
                ++pages;
            } catch (const Error& e) {
                links[test.name].push_back({label + " (no viewer: " + grader::escapeUntrusted(e.what(), grader::TextLayout::OneLine) + ")", ""});
            }
        }
    }
    return links;
}

}  // namespace rtlab::viewer
