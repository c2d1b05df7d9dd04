// Assignment a3: the uniform grid. Truth tables for each pinned rule (resolution, cell lookup,
// DDA set-up and step), the order of cells a walk visits against an exact oracle, and the
// generic accelerator checks (structure, hit sets, efficiency) on the hit-set scenes and the
// teapot in a stadium.
#include "framework/accel/grid/grid_structure_view.h"
#include "framework/core/pcg32.h"
#include "grader/kit/structure_tests.h"
#include "grader/a3_grid/a3_tests.h"
#include "grader/kit/image_tests.h"
#include "grader/a3_grid/given_grid.h"
#include "grader/a3_grid/grid_oracle.h"
#include "grader/wire/scene_codec.h"
#include "grader/kit/truth_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace rtlab::grader {
namespace {

constexpr const char* kA3 = "a3";
const std::string kStubResolution = a3Stubs().name("gridResolution");
const std::string kStubCell = a3Stubs().name("cellOfPoint");
const std::string kStubRange = a3Stubs().name("cellRange");
// The build's frame calls gridResolution before fillGridCells fills the cells.
const std::string kStubFill = a3Stubs().names({"gridResolution", "fillGridCells"});
const std::string kStubSetup = a3Stubs().name("ddaSetup");
const std::string kStubStep = a3Stubs().name("ddaStep");
const std::string kStubWalk = a3Stubs().names({"ddaSetup", "ddaStep"});
const std::string kStubClosest = a3Stubs().name("intersectGrid");
const std::string kStubOccluded = a3Stubs().name("occludedGrid");

using worker::GridFrame;

std::string describeCell(const GridCell& c) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "(%d, %d, %d)", c[0], c[1], c[2]);
    return buffer;
}

GridCell readCell(ByteReader& in) {
    GridCell c;
    for (int& v : c) v = in.get<int32_t>();
    return c;
}

// A frame of 4 x 2 x 2 unit cells over [0,4] x [0,2] x [-1,1]: every boundary is dyadic.
GridFrame unitFrame() { return frameOf(Bounds3f(Vec3(0, 0, -1), Vec3(4, 2, 1)), {4, 2, 2}); }

// --- Resolution -------------------------------------------------------------------------------

struct ResolutionCase {
    const char* id;
    worker::ResolutionCall call;
    std::array<int, 3> expected;  // derived by hand from the rule
};

std::vector<ResolutionCase> resolutionCases() {
    auto box = [](Vec3 lo, Vec3 hi) { return Bounds3f(lo, hi); };
    GridOptions lecture;          // C = 27, at most 64 per axis
    GridOptions one{1.0, 64}, eight{8.0, 64}, capped{27.0, 4};
    return {
        {"cube: cbrt(27 * 1000) = 30 cells per side", {box(Vec3(0), Vec3(10)), 1000, lecture}, {30, 30, 30}},
        {"4:2:1 box, N = 64: 12 cells along the longest axis", {box(Vec3(0), Vec3(4, 2, 1)), 64, lecture}, {12, 6, 3}},
        {"flat box: one cell across z", {box(Vec3(0, 0, 5), Vec3(1, 1, 5)), 8, lecture}, {6, 6, 1}},
        {"no primitives", {box(Vec3(0), Vec3(1)), 0, lecture}, {1, 1, 1}},
        {"a point: no extent", {box(Vec3(2), Vec3(2)), 5, lecture}, {1, 1, 1}},
        {"the cap: 300 cells per side wanted, 64 allowed", {box(Vec3(0), Vec3(1)), 1000000, lecture}, {64, 64, 64}},
        {"C = 1", {box(Vec3(0), Vec3(1)), 1000, one}, {10, 10, 10}},
        {"rounding to nearest: 3 x 1.8 x 0.6", {box(Vec3(0), Vec3(1.0f, 0.6f, 0.2f)), 1, lecture}, {3, 2, 1}},
        {"a cap of 4", {box(Vec3(0), Vec3(1)), 1000, capped}, {4, 4, 4}},
        {"negative coordinates, C = 8", {box(Vec3(-3, -1, -1), Vec3(-1, 1, 1)), 1, eight}, {2, 2, 2}},
    };
}

TestGroup resolutionGroup() {
    return tableGroup(kA3, "a3 resolution rule", "a3/cells/resolution", kStubResolution, worker::kTaskGridResolution, resolutionCases(),
                      [](const ResolutionCase& c, ByteReader& in) {
                          GridCell got = readCell(in);
                          return got == c.expected ? std::string() : expectedGot(describeCell(c.expected), describeCell(got));
                      });
}

// --- Cell of a point, cell range of a box ------------------------------------------------------

struct PointCase {
    const char* id;
    Vec3 p;
    GridCell expected;
};

std::vector<PointCase> pointCases() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {
        {"inside the first cell", {0.5f, 0.5f, -0.5f}, {0, 0, 0}},
        {"on the upper faces: the last cell", {4, 2, 1}, {3, 1, 1}},
        {"on interior boundaries: the upper cell", {1, 1, 0}, {1, 1, 1}},
        {"below the grid: clamped to 0 (floor, not truncation)", {-0.5f, -3, -2}, {0, 0, 0}},
        {"above the grid: clamped to the last cell", {9, 9, 9}, {3, 1, 1}},
        {"one ulp below the lower corner", {std::nextafter(0.0f, -1.0f), std::nextafter(0.0f, -1.0f), std::nextafter(-1.0f, -2.0f)}, {0, 0, 0}},
        {"NaN goes to cell 0", {nan, 0.5f, 0.5f}, {0, 0, 1}},
        {"-0.0 offsets", {-0.0f, -0.0f, -1}, {0, 0, 0}},
        {"just below the upper faces", {std::nextafter(4.0f, 0.0f), 1.5f, std::nextafter(1.0f, 0.0f)}, {3, 1, 1}},
        {"coordinates beyond int range", {1e30f, -1e30f, 0.25f}, {3, 0, 1}},
    };
}

struct RangeCase {
    const char* id;
    Bounds3f box;
    GridCell lower, upper;
};

std::vector<RangeCase> rangeCases() {
    return {
        {"a box over three by two cells", Bounds3f(Vec3(0.5f, 0, -1), Vec3(2.5f, 1.5f, -0.5f)), {0, 0, 0}, {2, 1, 0}},
        {"a box ending on a boundary enters the next cell", Bounds3f(Vec3(0.2f, 0.2f, -0.8f), Vec3(1, 0.8f, -0.2f)), {0, 0, 0}, {1, 0, 0}},
        {"a flat box on a boundary", Bounds3f(Vec3(2, 0.5f, -0.5f), Vec3(2, 1.5f, 0.5f)), {2, 0, 0}, {2, 1, 1}},
        {"a box larger than the grid", Bounds3f(Vec3(-10), Vec3(10)), {0, 0, 0}, {3, 1, 1}},
    };
}

TestGroup cellGroup() {
    auto points = std::make_shared<std::vector<PointCase>>(pointCases());
    auto ranges = std::make_shared<std::vector<RangeCase>>(rangeCases());
    // On a grid flat in z, inverseWidth.z is 0: every point is in z-cell 0.
    auto flat = std::make_shared<GridFrame>(frameOf(Bounds3f(Vec3(0, 0, 5), Vec3(2, 2, 5)), {2, 2, 1}));
    auto flatPoints = std::make_shared<std::vector<PointCase>>(std::vector<PointCase>{
        {"flat grid: a point above its plane", {1.5f, 0.5f, 7}, {1, 0, 0}},
        {"flat grid: a point below its plane", {0.5f, 1.5f, -3}, {0, 1, 0}}});
    auto pointPhase = [](const GridFrame& frame, const std::vector<PointCase>& cases) {
        ByteWriter shared;
        shared.put(frame);
        return tablePhase(kStubCell, worker::kTaskGridCell, cases, [](const PointCase& c) { return c.p; }, std::move(shared));
    };
    ByteWriter rangeFrame;
    rangeFrame.put(unitFrame());
    TestGroup group{kA3, "a3 cells of points and boxes",
                    {pointPhase(unitFrame(), *points), pointPhase(*flat, *flatPoints),
                     tablePhase(kStubRange, worker::kTaskGridRange, *ranges, [](const RangeCase& c) { return c.box; }, std::move(rangeFrame))},
                    {}};
    group.score = [points, flatPoints, ranges](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult cells = makeResult(kA3, "a3/cells/cell-of-point"), range = makeResult(kA3, "a3/cells/cell-range");
        scoreTable({TablePart<PointCase>{run.phases[0], *points}, TablePart<PointCase>{run.phases[1], *flatPoints}}, cells,
                   [](const PointCase& c, ByteReader& in) {
                       GridCell got = readCell(in);
                       return caseLine(std::string(c.id) + " p = " + describeVec(c.p),
                                       got == c.expected ? "" : expectedGot(describeCell(c.expected), describeCell(got)));
                   });
        scoreTable(run.phases[2], *ranges, range, [](const RangeCase& c, ByteReader& in) {
            GridCell lower = readCell(in), upper = readCell(in);
            bool right = lower == c.lower && upper == c.upper;
            return right ? std::string()
                         : expectedGot(describeCell(c.lower) + " .. " + describeCell(c.upper), describeCell(lower) + " .. " + describeCell(upper));
        });
        results.push_back(std::move(cells));
        results.push_back(std::move(range));
    };
    return group;
}

// --- The DDA's set-up and step -----------------------------------------------------------------

Ray makeRay(Vec3 o, Vec3 d) {
    Ray r;
    r.origin = o;
    r.direction = d;
    return r;
}

struct SetupCase {
    const char* id;
    worker::DdaSetupCall call;
    DdaState expected;  // derived by hand on unitFrame(): every value is exact
};

std::vector<SetupCase> setupCases() {
    const float inf = kInfinity;
    return {
        {"entering from -x along +x", {makeRay({-1, 0.5f, -0.5f}, {1, 0, 0}), 1, 5}, {{0, 0, 0}, {1, 0, 0}, {2, inf, inf}, {1, inf, inf}, 5}},
        {"entering the +x face along -x, with -0.0 and +0.0 components", {makeRay({5, 0.5f, 0.5f}, {-1, -0.0f, 0.0f}), 1, 5},
         {{3, 0, 1}, {-1, 0, 0}, {2, inf, inf}, {1, inf, inf}, 5}},
        {"starting inside, all three axes moving", {makeRay({1.5f, 1.5f, 0.25f}, {0.5f, -0.25f, 2}), 0, 3},
         {{1, 1, 1}, {1, -1, 1}, {1, 2, 0.375f}, {2, 4, 0.5f}, 3}},
        {"-0.0 on x: step 0, never the next axis", {makeRay({0.5f, -1, 0.5f}, {-0.0f, 1, 0}), 1, 3},
         {{0, 0, 1}, {0, 1, 0}, {inf, 2, inf}, {inf, 1, inf}, 3}},
        {"moving down from inside: the boundary ahead is the cell's own lower face", {makeRay({2.5f, 1.25f, 0.75f}, {-2, -1, -4}), 0, 1},
         {{2, 1, 1}, {-1, -1, -1}, {0.25f, 0.25f, 0.1875f}, {0.5f, 1, 0.25f}, 1}},
    };
}

std::string stateProblem(const DdaState& expected, const DdaState& got) {
    auto close = [](float a, float b) { return a == b || std::abs(a - b) <= 1e-6f * std::max(std::abs(a), std::abs(b)); };
    std::string problem;
    if (got.cell != expected.cell) problem += "cell " + describeCell(got.cell) + " instead of " + describeCell(expected.cell) + "; ";
    if (got.step != expected.step) problem += "step " + describeCell(got.step) + " instead of " + describeCell(expected.step) + "; ";
    for (int a = 0; a < 3; ++a) {
        const char* axis[] = {"x", "y", "z"};
        if (!close(got.tNext[a], expected.tNext[a]))
            problem += std::string("tNext.") + axis[a] + " " + formatNumber(got.tNext[a]) + " instead of " + formatNumber(expected.tNext[a]) + "; ";
        if (!close(got.tDelta[a], expected.tDelta[a]))
            problem += std::string("tDelta.") + axis[a] + " " + formatNumber(got.tDelta[a]) + " instead of " + formatNumber(expected.tDelta[a]) + "; ";
    }
    if (got.tExit != expected.tExit) problem += "tExit " + formatNumber(got.tExit) + " instead of " + formatNumber(expected.tExit) + "; ";
    if (!problem.empty()) problem.resize(problem.size() - 2);
    return problem;
}

struct StepCase {
    const char* id;
    worker::DdaStepCall call;
    bool inside;
    DdaState expected;
};

std::vector<StepCase> stepCases() {
    const float inf = kInfinity;
    std::array<int32_t, 3> res{4, 4, 4};
    auto state = [](GridCell cell, std::array<int, 3> step, Vec3 next, Vec3 delta, float exit) { return DdaState{cell, step, next, delta, exit}; };
    return {
        {"x nearest", {state({1, 1, 1}, {1, 1, 1}, {1, 2, 3}, {1, 1, 1}, 10), res}, true, state({2, 1, 1}, {1, 1, 1}, {2, 2, 3}, {1, 1, 1}, 10)},
        {"tie x = y < z: y (the higher axis)", {state({1, 1, 1}, {1, 1, 1}, {1, 1, 2}, {1, 1, 1}, 10), res}, true,
         state({1, 2, 1}, {1, 1, 1}, {1, 2, 2}, {1, 1, 1}, 10)},
        {"tie x = z < y: z", {state({1, 1, 1}, {1, -1, 1}, {1, 2, 1}, {1, 1, 1}, 10), res}, true,
         state({1, 1, 2}, {1, -1, 1}, {1, 2, 2}, {1, 1, 1}, 10)},
        {"tie y = z < x: z", {state({1, 1, 1}, {1, 1, -1}, {2, 1, 1}, {1, 1, 1}, 10), res}, true,
         state({1, 1, 0}, {1, 1, -1}, {2, 1, 2}, {1, 1, 1}, 10)},
        {"all three equal: z, and only z", {state({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 2, 3}, 10), res}, true,
         state({1, 1, 2}, {1, 1, 1}, {1, 1, 4}, {1, 2, 3}, 10)},
        {"the next crossing is beyond tExit: over, nothing changes", {state({1, 1, 1}, {1, 1, 1}, {5, 6, 7}, {1, 1, 1}, 4), res}, false,
         state({1, 1, 1}, {1, 1, 1}, {5, 6, 7}, {1, 1, 1}, 4)},
        {"a crossing exactly at tExit still steps", {state({1, 1, 1}, {1, 1, 1}, {4, 6, 7}, {1, 1, 1}, 4), res}, true,
         state({2, 1, 1}, {1, 1, 1}, {5, 6, 7}, {1, 1, 1}, 4)},
        {"stepping out at the top", {state({3, 1, 1}, {1, 1, 1}, {1, 2, 3}, {1, 1, 1}, 10), res}, false,
         state({4, 1, 1}, {1, 1, 1}, {2, 2, 3}, {1, 1, 1}, 10)},
        {"stepping out at the bottom", {state({2, 0, 2}, {1, -1, 1}, {3, 1, 2}, {1, 1, 1}, 10), res}, false,
         state({2, -1, 2}, {1, -1, 1}, {3, 2, 2}, {1, 1, 1}, 10)},
        {"no direction at all: every tNext infinite, the walk is over", {state({1, 1, 1}, {0, 0, 0}, {inf, inf, inf}, {inf, inf, inf}, inf), res},
         false, state({1, 1, 1}, {0, 0, 0}, {inf, inf, inf}, {inf, inf, inf}, inf)},
        {"a zero direction component (tNext = inf) is never stepped", {state({1, 1, 1}, {0, 1, 0}, {inf, 3, inf}, {inf, 1, inf}, 10), res}, true,
         state({1, 2, 1}, {0, 1, 0}, {inf, 4, inf}, {inf, 1, inf}, 10)},
    };
}

TestGroup ddaGroup() {
    auto setups = std::make_shared<std::vector<SetupCase>>(setupCases());
    auto steps = std::make_shared<std::vector<StepCase>>(stepCases());
    ByteWriter setupFrame;
    setupFrame.put(unitFrame());
    TestGroup group{kA3, "a3 DDA set-up and step",
                    {tablePhase(kStubSetup, worker::kTaskDdaSetup, *setups, std::move(setupFrame)), tablePhase(kStubStep, worker::kTaskDdaStep, *steps)},
                    {}};
    group.score = [setups, steps](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult setup = makeResult(kA3, "a3/dda/setup"), step = makeResult(kA3, "a3/dda/step");
        scoreTable(run.phases[0], *setups, setup, [](const SetupCase& c, ByteReader& in) {
            return caseLine(std::string(c.id) + " " + describeRay(c.call.ray) + " tEnter " + formatNumber(c.call.tEnter),
                            stateProblem(c.expected, in.get<DdaState>()));
        });
        scoreTable(run.phases[1], *steps, step, [](const StepCase& c, ByteReader& in) {
            bool inside = in.get<uint8_t>() != 0;
            std::string problem = stateProblem(c.expected, in.get<DdaState>());
            if (inside != c.inside) problem = std::string("returned ") + (inside ? "true" : "false") + (problem.empty() ? "" : "; " + problem);
            return problem;
        });
        results.push_back(std::move(setup));
        results.push_back(std::move(step));
    };
    return group;
}

// --- The order of cells a walk visits -----------------------------------------------------------

struct Walk {
    worker::DdaSetupCall call;
    std::vector<GridCell> expected;
};

// Where a ray's segment [tMin, tMax] lies inside the frame's box, in double, or false.
bool segmentInBox(const Bounds3f& box, const Ray& ray, float* tEnter, float* tExit) {
    double t0 = ray.tMin, t1 = ray.tMax;
    for (int a = 0; a < 3; ++a) {
        double o = ray.origin[a], d = ray.direction[a], lo = box.lower[a], hi = box.upper[a];
        if (d == 0.0) {
            if (o < lo || o > hi) return false;
            continue;
        }
        double n = (lo - o) / d, f = (hi - o) / d;
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
    }
    if (!(t0 < t1)) return false;
    *tEnter = float(t0);
    *tExit = float(t1);
    return true;
}

std::vector<Walk> walks(const GridFrame& frame, uint64_t seed, size_t count) {
    Pcg32 rng(seed, 17);
    const Bounds3f& box = frame.bounds;
    Vec3 size = box.diagonal();
    auto inBox = [&](float margin) {
        return box.lower - margin * size + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * (1.0f + 2.0f * margin) * size;
    };
    std::vector<Walk> list;
    for (size_t attempt = 0; list.size() < count && attempt < 20 * count; ++attempt) {
        Ray ray;
        ray.origin = attempt % 3 == 0 ? inBox(0.0f) : inBox(1.0f);
        ray.direction = inBox(0.0f) - ray.origin;
        if (attempt % 5 == 1) ray.direction[attempt % 3] = attempt % 2 ? -0.0f : 0.0f;
        float tEnter, tExit;
        if (!segmentInBox(box, ray, &tEnter, &tExit)) continue;
        worker::DdaSetupCall call{ray, tEnter, tExit};
        if (auto cells = exactCellWalk(frame, ray, tEnter, tExit)) list.push_back({call, std::move(*cells)});
    }
    return list;
}

TestGroup cellOrderGroup(uint64_t seed) {
    // A cube of 8^3 dyadic cells and a long, thin grid with widths that are not dyadic.
    std::vector<GridFrame> frames{frameOf(Bounds3f(Vec3(0), Vec3(8)), {8, 8, 8}),
                                  frameOf(Bounds3f(Vec3(-2, 0, 0.1f), Vec3(6, 1, 3.3f)), {16, 3, 7})};
    auto expected = std::make_shared<std::vector<std::vector<Walk>>>();
    TestGroup group{kA3, "a3 cell order", {}, {}};
    for (size_t f = 0; f < frames.size(); ++f) {
        expected->push_back(walks(frames[f], seed + f, 300));
        std::vector<worker::DdaSetupCall> calls;
        for (const Walk& w : expected->back()) calls.push_back(w.call);
        ByteWriter input;
        input.put(frames[f]);
        input.putVector(calls);
        group.phases.push_back(makePhase(kStubWalk, worker::kTaskDdaWalk, std::move(input), kStubSetup));
    }
    group.score = [expected, frames](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(kA3, "a3/dda/cell-order");
        CaseTally tally(result);
        for (size_t f = 0; f < expected->size(); ++f) {
            if (failedPhaseResult(run.phases[f], result)) {
                results.push_back(std::move(result));
                return;
            }
            ByteReader in(run.phases[f].data);
            for (const Walk& walk : (*expected)[f]) {
                auto n = in.get<uint32_t>();
                if (n > worker::kMaxWalkCells + 1) throw WireError("a walk longer than the limit");
                std::vector<GridCell> got;
                for (uint32_t i = 0; i < n; ++i) got.push_back(readCell(in));
                std::string problem;
                if (n > worker::kMaxWalkCells) problem = "the walk does not end (more than " + std::to_string(worker::kMaxWalkCells) + " cells)";
                else if (got != walk.expected) {
                    size_t k = 0;
                    while (k < got.size() && k < walk.expected.size() && got[k] == walk.expected[k]) ++k;
                    problem = std::to_string(got.size()) + " cells instead of " + std::to_string(walk.expected.size()) + "; cell " +
                              std::to_string(k) + " is " + (k < got.size() ? describeCell(got[k]) : "missing") + ", expected " +
                              (k < walk.expected.size() ? describeCell(walk.expected[k]) : "none");
                }
                std::string id = "grid " + std::to_string(f) + " " + describeRay(walk.call.ray) + " [" + formatNumber(walk.call.tEnter) +
                                 ", " + formatNumber(walk.call.tExit) + "]";
                tally.record(id, problem);
                if (!problem.empty() && result.failedCases.size() < kViewerCasesPerTest) {
                    // The viewer draws both walks in one grid: the expected cells, the student's, both.
                    FailedCase failed;
                    failed.title = "a3/dda/cell-order: grid " + std::to_string(f);
                    failed.notes = {id + ": " + problem};
                    CaseRay& ray = failed.rays.emplace_back();
                    ray.ray = walk.call.ray;
                    ray.ray.tMin = walk.call.tEnter;
                    ray.ray.tMax = walk.call.tExit;
                    ray.label = "the walk's ray over [tEnter, tExit]";
                    failed.cells = CaseCells{frames[f].bounds,
                                             {frames[f].resolution[0], frames[f].resolution[1], frames[f].resolution[2]},
                                             walk.expected,
                                             got};
                    addFailedCase(result, std::move(failed));
                }
            }
        }
        tally.finish();
        if (result.status == TestStatus::Passed)
            result.details.push_back(std::to_string((*expected)[0].size() + (*expected)[1].size()) +
                                     " walks on two grids, every cell in order (rays through edges and corners are left out: their order is a tie)");
        results.push_back(std::move(result));
    };
    return group;
}

// --- The whole grid on the hit-set scenes --------------------------------------------------------

struct BuiltGrid {
    GridFrame frame;
    std::vector<uint32_t> cellStart, primIndices;
};

// The grid as the viewer draws it, when its lists fit its resolution (one start per cell and
// one more, never decreasing) and it has few enough cells to draw; otherwise nothing.
std::optional<StructureView> gridView(const BuiltGrid& grid) {
    constexpr size_t kMaxDrawnCells = size_t(1) << 20;
    UniformGrid frame;
    frame.bounds = grid.frame.bounds;
    for (int a = 0; a < 3; ++a) {
        if (grid.frame.resolution[a] < 1) return std::nullopt;
        frame.resolution[a] = grid.frame.resolution[a];
    }
    frame.cellWidth = grid.frame.cellWidth;
    frame.inverseWidth = grid.frame.inverseWidth;
    if (frame.cellCount() > kMaxDrawnCells || grid.cellStart.size() != frame.cellCount() + 1) return std::nullopt;
    if (!std::is_sorted(grid.cellStart.begin(), grid.cellStart.end())) return std::nullopt;
    return gridStructureView(frame, grid.cellStart, grid.primIndices);
}

std::optional<BuiltGrid> readGrid(const PhaseOutcome& outcome, std::string* problem) {
    try {
        ByteReader in(outcome.data);
        BuiltGrid grid;
        grid.frame = in.get<GridFrame>();
        grid.cellStart = in.getVector<uint32_t>(size_t(1) << 28);
        grid.primIndices = in.getVector<uint32_t>(size_t(1) << 28);
        return grid;
    } catch (const WireError& e) {
        *problem = std::string("the build sent malformed results: ") + e.what();
        return std::nullopt;
    }
}

// The structure invariants: the frame the rule gives, the compact cell array well formed, and
// every primitive in exactly the cells its box overlaps (so no reference is missing or extra).
std::vector<std::string> gridProblems(const BuiltGrid& grid, const std::vector<Bounds3f>& primBounds, const GridOptions& options) {
    std::vector<std::string> problems;
    GridFrame want = expectedFrame(primBounds, options);
    if (grid.frame.resolution != want.resolution) {
        problems.push_back("resolution " + describeCell(grid.frame.resolution) + ", the rule gives " + describeCell(want.resolution) +
                           " (gridResolution)");
        return problems;
    }
    size_t cells = size_t(want.resolution[0]) * want.resolution[1] * want.resolution[2];
    if (grid.cellStart.size() != cells + 1 || grid.cellStart.front() != 0 || grid.cellStart.back() != grid.primIndices.size()) {
        problems.push_back("cellStart must have one entry per cell plus one, start at 0 and end at primIndices.size()");
        return problems;
    }
    auto cellIndex = [&](const GridCell& c) { return (size_t(c[2]) * want.resolution[1] + c[1]) * want.resolution[0] + c[0]; };
    std::vector<std::vector<uint32_t>> expected(cells);
    for (uint32_t prim = 0; prim < primBounds.size(); ++prim) {
        if (!isPlaceable(primBounds[prim])) continue;
        GridCell lo = expectedCell(want, primBounds[prim].lower), hi = expectedCell(want, primBounds[prim].upper);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) expected[cellIndex({x, y, z})].push_back(prim);
    }
    size_t wrongCells = 0;
    for (size_t c = 0; c < cells; ++c) {
        if (grid.cellStart[c] > grid.cellStart[c + 1]) {
            problems.push_back("cellStart decreases at cell " + std::to_string(c));
            return problems;
        }
        std::vector<uint32_t> got(grid.primIndices.begin() + grid.cellStart[c], grid.primIndices.begin() + grid.cellStart[c + 1]);
        if (got == expected[c]) continue;
        if (wrongCells++ < 5) {
            std::set<uint32_t> should(expected[c].begin(), expected[c].end()), have(got.begin(), got.end());
            std::vector<std::string> what;
            if (have == should) what.push_back("the right primitives, not in increasing order");
            for (uint32_t p : should)
                if (!have.count(p) && what.size() < 8) what.push_back("missing " + std::to_string(p));
            for (uint32_t p : have)
                if (!should.count(p) && what.size() < 8) what.push_back("extra " + std::to_string(p));
            std::string line;
            for (const std::string& w : what) line += (line.empty() ? "" : ", ") + w;
            problems.push_back("cell " + std::to_string(c) + ": " + line);
        }
    }
    if (wrongCells > 5) problems.push_back(std::to_string(wrongCells - 5) + " more cells wrong");
    return problems;
}

// The grid as the generic structure tests see it, with the lecture's C = 27.
StructurePlugin gridPlugin() {
    const GridOptions options;
    StructurePlugin plugin;
    plugin.assignment = kA3;
    plugin.label = "grid";
    plugin.drawing = "grid";
    plugin.draw = drawCells;
    plugin.traceAccelerator = "grid";
    plugin.build = [options](const Scene& scene) {
        ByteWriter input;
        writeScene(scene, input);
        input.put(options);
        return makePhase(kStubFill, worker::kTaskGridBuild, std::move(input), a3Stubs().name("gridResolution"));
    };
    plugin.queryTask = worker::kTaskGridQuery;
    plugin.queries = {{"closest-hits", worker::QueryKind::Closest, kStubClosest}, {"any-hits", worker::QueryKind::Occluded, kStubOccluded}};
    plugin.given = givenGrid;
    plugin.givenQueryTask = worker::kTaskGridGivenQuery;
    plugin.check = [options](const PhaseOutcome& build, const std::vector<Bounds3f>& primBounds, CheckScope) {
        StructureReport report;
        std::string problem;
        auto grid = readGrid(build, &problem);
        if (!grid) {
            report.problems.push_back(problem);
            return report;
        }
        report.problems = gridProblems(*grid, primBounds, options);
        report.view = gridView(*grid);
        if (report.view) report.gridResolution = std::array<int, 3>{grid->frame.resolution[0], grid->frame.resolution[1], grid->frame.resolution[2]};
        report.summary = "resolution " + describeCell(grid->frame.resolution) + ", " + std::to_string(grid->primIndices.size()) +
                         " references (" + formatNumber(double(grid->primIndices.size()) / double(std::max<size_t>(1, primBounds.size()))) +
                         " per primitive)";
        return report;
    };
    // 70000 identical triangles over the whole grid put every one of them into all 64 x 64
    // cells: 287 million references, which no correct grid avoids (the case is the BVH's leaf
    // size limit).
    plugin.skipDegenerate = {"BVH-11 70000 identical primitives"};
    return plugin;
}

}  // namespace

std::vector<TestGroup> a3Groups(GradingContext& context) {
    std::vector<TestGroup> groups;
    groups.push_back(resolutionGroup());
    groups.push_back(cellGroup());
    groups.push_back(ddaGroup());
    groups.push_back(cellOrderGroup(context.seed));
    StructurePlugin grid = gridPlugin();
    for (TestGroup& g : structureGroups(grid, context)) groups.push_back(std::move(g));
    // The stadium: graded for its hits, never for speed (a uniform grid is slow there by design).
    groups.push_back(structureSceneGroup(grid, prepareScene(teapotInAStadium(context.modelsDir), context.seed), context));
    // Every scene rendered through the structure.
    for (TestGroup& g : imageGroups(context, {"a3", "grid", "the renderer with --accel grid (a0 + a3 functions)", a3Stubs().name("gridResolution")}))
        groups.push_back(std::move(g));
    return groups;
}

}  // namespace rtlab::grader
