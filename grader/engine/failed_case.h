// A failing case as plain data, so the HTML report can link it to the viewer
// (docs/viewer.md#from-the-report): the ray, the student's answer and the expected one, the scene, and where a
// test has them the student's structure or DDA cells. The grader records it while scoring; the
// viewer (viewer/report_viewers.h, a layer above) turns it into a page. The grader never
// includes the viewer, so this is all it knows of it.
//
// Everything here is either the grader's own data or a worker's answer that the scoring already
// validated (numbers, counts within their wire limits); strings are written by the grader.
#pragma once

#include "framework/accel/structure_drawing.h"
#include "framework/accel/structure_view.h"
#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/traversal_trace.h"
#include "framework/scene/scene.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::grader {

// At most this many failing cases of one test get a viewer page: the first few say what is
// wrong, and a report of a broken submission stays small.
inline constexpr size_t kViewerCasesPerTest = 3;
// Per case: the rays drawn and the cells of one DDA walk kept (a walk that does not end is cut).
inline constexpr size_t kViewerRaysPerCase = 8;
inline constexpr size_t kViewerCellsPerWalk = 4096;

// What one query answered: a closest hit (prim at t, or a miss) or an any-hit (blocked or not).
struct CaseAnswer {
    enum class Kind : uint8_t { None, Closest, AnyHit };
    Kind kind = Kind::None;  // None: no answer recorded
    bool hit = false;
    float t = kInfinity;
    uint32_t prim = kNoHit;

    static CaseAnswer closest(uint32_t prim, float t) { return {Kind::Closest, prim != kNoHit, t, prim}; }
    static CaseAnswer anyHit(bool blocked) { return {Kind::AnyHit, blocked, kInfinity, kNoHit}; }
};

struct CaseRay {
    Ray ray;
    std::string label;  // "ray 17 (random)"
    CaseAnswer student, expected;
    // What the walks did, where the test knows it: a visit-order test's primitives tested or
    // leaves entered, in order, as the student's worker listed them (already range-checked) and
    // as the exact order has them.
    std::optional<TraversalTrace> studentTrace, expectedTrace;
};

// A DDA walk of a3: the cells expected and the cells the student's walk entered, in one grid.
struct CaseCells {
    Bounds3f bounds;
    std::array<int, 3> resolution{1, 1, 1};
    std::vector<std::array<int, 3>> expected, student;
};

// A failed image: the files the report shows, and the pixel where render and reference differ
// most (the viewer loads its camera ray).
struct CaseImage {
    std::string render, reference, difference;  // absolute paths; any may be empty
    uint32_t camera = 0;                        // index into the scene's cameras
    int width = 0, height = 0;
    std::optional<std::array<int, 2>> worstPixel;
    std::string legend;
};

struct FailedCase {
    std::string title;               // "[bunny] ray 17"
    std::vector<std::string> notes;  // what was expected and what came back, in words
    std::shared_ptr<const Scene> scene;  // the graded scene (shared with the grading run); may be null
    std::string accelerator;             // the structure's name on the page ("bvh")
    StructureDrawer draw = nullptr;      // how `structure` is drawn (drawBvh, drawCells, ...)
    std::optional<StructureView> structure;  // what the student's build returned, when it could be read
    std::optional<std::array<int, 3>> gridResolution;  // a uniform grid's: its cells per axis
    // The registry name (accelerator_registry.h) that builds the student's structure in a worker,
    // so the grader can record the student's walk of `rays` (failed_case_traces.h); empty: none.
    std::string traceAccelerator;
    std::vector<CaseRay> rays;
    std::optional<CaseCells> cells;
    std::optional<CaseImage> image;
};

}  // namespace rtlab::grader
