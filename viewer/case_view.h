// The viewer's API (docs/viewer.md): everything one page shows, and the function that writes it.
// `rtlab view` fills a CaseView from the code it links; the grader's HTML report fills one per
// failing case from what its workers returned, and links to the folder.
//
//   CaseView view;
//   view.title = "a1/closest-hits/bunny: ray 17";          // text, never markup
//   view.notes = {"expected prim 12 at t = 3.5, got a miss"};
//   view.scene = &scene;                                   // geometry, prim ids as PrimitiveSet numbers them
//   view.acceleratorName = "bvh-median";                   // named on the page
//   view.draw = structureDrawer("bvh-median");             // the registry's drawing for it
//   view.structure = bvhStructureView(bvh);                // what the student built
//   RayCase& r = view.rays.emplace_back();
//   r.ray = ray;
//   r.student = RayAnswer::closest(hit.prim, hit.t);       // the student's answer ...
//   r.studentTrace = decodeTraversalTrace(bytesFromWorker); // ... and its trace (untrusted: decoded)
//   r.expected = RayAnswer::closest(oracleHit.prim, float(oracleHit.t));
//   r.expectedTrace = referenceTrace;                      // optional: the reference's walk
//   writeCaseViewer("report/viewer/a1-closest-hits-bunny-17", view);
//
// Then index.html in that folder opens from file:// in Chromium and Firefox, with no server and
// no network: three.js, the page's script and the data are inside it.
//
// Trust: every string of a CaseView is shown with textContent, never parsed as markup; numbers
// travel as typed arrays in one compressed block that the page parses (never evaluates); each
// list is capped by ViewerLimits, and a StructureView or trace that breaks its own rules is
// shown as far as it is sound (indices out of range are dropped, counted and said in a note).
#pragma once

#include "framework/accel/structure_drawing.h"
#include "framework/accel/structure_view.h"
#include "framework/core/ray.h"
#include "framework/interface/grid.h"
#include "framework/interface/traversal_trace.h"
#include "framework/scene/camera.h"
#include "framework/scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::viewer {

// What one query answered. A closest-hit query hits a primitive at t; an any-hit query only
// says whether the segment is blocked (prim and t unknown).
struct RayAnswer {
    enum class Kind : uint8_t { None, Closest, AnyHit };
    Kind kind = Kind::None;  // None: no answer (the code threw, or nothing was recorded)
    bool hit = false;
    float t = kInfinity;
    uint32_t prim = kNoHit;

    static RayAnswer closest(uint32_t prim, float t) { return {Kind::Closest, prim != kNoHit, t, prim}; }
    static RayAnswer anyHit(bool blocked) { return {Kind::AnyHit, blocked, kInfinity, kNoHit}; }
};

// One ray with the student's way through the structure and the expected one.
struct RayCase {
    Ray ray;
    std::string label;  // "camera ray of pixel (120, 80)", "shadow ray to light 0"
    RayAnswer student, expected;
    std::optional<TraversalTrace> studentTrace, expectedTrace;
    std::string expectedSource = "the exact oracle";  // who gave `expected`, e.g. "rtlab-solution"
};

// a3's DDA: the cells two walks entered, drawn in one grid (expected, the student's, both).
struct DdaCells {
    Bounds3f bounds;
    std::array<int, 3> resolution{1, 1, 1};
    size_t ray = 0;  // which RayCase the walks belong to
    std::vector<GridCell> expected, student;
};

// A rendered image and what belongs to it (docs/viewer.md#image-to-ray). PNG files are copied
// into the folder; any may be empty (not shown).
struct ImageSet {
    std::filesystem::path render, heatMap, reference, difference;
    std::string legend;  // one line under the images ("mean error 0.012, 3.1 % of pixels over 0.05")
    int width = 0, height = 0;
    CameraFilm film;  // the camera's film for width x height: a click makes that pixel's ray
    // Per pixel (row by row from the top), the camera ray's hit distance (inf: a miss) and, per
    // point light, whether the hit point's shadow ray is blocked; either may be empty.
    std::vector<float> hitT;
    std::vector<uint8_t> shadowBlocked;  // pixel * lights + light
    std::vector<Vec3> lights;            // point-light positions
    std::optional<std::array<int, 2>> selectedPixel;
    std::string pixelCommand;  // shown for a clicked pixel, "X,Y" replaced by its coordinates
};

// a6: one sampler's points and its histogram against the exact counts.
struct SamplerPanel {
    std::string name;     // "sampleCosineHemisphere"
    std::string domain;   // "hemisphere", "cone", "sphere", "triangle", "spherical triangle"
    std::vector<Vec2> unitSquare;  // the u given to the sampler
    std::vector<Vec3> mapped;      // what it returned (directions, or points of the triangle)
    std::array<Vec3, 3> triangle{};  // triangle and spherical triangle: the corners (and the
    Vec3 origin{0.0f};               // point the spherical triangle is seen from)
    float cosThetaMax = 0.0f;        // cone
    std::vector<double> observed, expected;  // per histogram cell
    std::string cellsNote;  // how the cells are laid out ("20 bands of z x 40 sectors of phi")
    // Cells rows x cols (then one cell outside): directions' bands of z (from zMin to 1) by
    // sectors of phi, drawn as the histogram of z and a map of each cell's deviation; 0: a list.
    int rows = 0, cols = 0;
    double zMin = 0.0;
    double chiSquare = 0.0, pValue = 1.0;
    int dof = 0;
    std::string error;  // non-empty: the sampler threw (NotImplemented, ...) and this says what
};

// a6: one estimator's error against its closed form as the sample count grows.
struct EstimatorCurve {
    std::string name;  // "estimateTriangleLightBySolidAngle"
    std::vector<double> samples, rmsError;  // per point: N and the RMS relative error over runs
    double slope = 0.0;                     // of log error against log N (-0.5 for plain Monte Carlo)
    std::string error;
};

// Caps on what one page carries (docs/viewer.md#scale). The defaults keep a page of the bunny
// under 2 MB and one of the sphereflake under 64 MB.
struct ViewerLimits {
    size_t maxNodes = 8192;              // a tree's top levels, plus every node a trace visits
    size_t maxCells = size_t(1) << 18;   // a grid's occupied cells
    size_t maxTraceOps = 1u << 16;       // per trace
    size_t maxRays = 64;
    size_t maxDdaCells = 1u << 16;
    size_t maxSamplerPoints = 4096;      // drawn; the histograms count every sample
    size_t maxTriangles = size_t(1) << 22;
    size_t maxTextBytes = 4096;          // per string
};

struct CaseView {
    std::string title;
    std::vector<std::string> notes;
    const Scene* scene = nullptr;  // not owned; null: no geometry (an a6 page)
    std::string acceleratorName;   // the structure's --accel name, as the page names it
    // How the structure is drawn: structureDrawer(acceleratorName) (framework/accel/structure_drawing.h),
    // or, where the registry may not be linked (rtlab-grader links no assignment code), the
    // structure's drawing function itself; unset: drawLevels.
    StructureDrawer draw = nullptr;
    std::optional<StructureView> structure;
    std::vector<RayCase> rays;
    std::optional<DdaCells> dda;
    // For a uniform grid's view (a root whose children are the cells in cellIndex order): its
    // resolution, so cells are named by their coordinates.
    std::optional<std::array<int, 3>> gridResolution;
    std::optional<ImageSet> images;
    std::vector<SamplerPanel> samplers;
    std::vector<EstimatorCurve> estimators;
    ViewerLimits limits;
};

// Writes dir/index.html (and the images it shows). dir must not exist, be empty, or hold a
// viewer written before (it is then replaced whole); anything else is refused with an
// rtlab::Error naming dir, and nothing is written. The folder is built beside dir and renamed
// into place, so a failure leaves no half-written viewer.
void writeCaseViewer(const std::filesystem::path& dir, const CaseView& view);

// The file that marks a folder as a viewer (so a second `rtlab view -o` may replace it).
inline constexpr const char* kViewerMarker = ".rtlab-viewer";

}  // namespace rtlab::viewer
