// a3's functions on the grader's inputs: the resolution rule, cell lookups, the DDA's set-up,
// step and walk, a whole grid build and traversals of the grid that build produced (those two
// through the grid's adapter, as the accelerator builds and queries it).
#include "framework/accel/grid/grid_adapter.h"
#include "framework/interface/a3_grid.h"
#include "grader/wire/scene_codec.h"
#include "grader/a3_grid/wire/grid_codec.h"
#include "grader/worker/structure_queries.h"
#include "grader/a3_grid/wire/grid_inputs.h"
#include "grader/worker/worker_tasks.h"

namespace rtlab::grader::worker {
namespace {

constexpr uint64_t kMaxCalls = uint64_t(1) << 20;
// Grids the grader sends have at most 1024 cells per axis (GridOptions::maxResolution).
constexpr int32_t kMaxFrameResolution = 1024;

UniformGrid gridOf(const GridFrame& frame) {
    UniformGrid grid;
    for (int a = 0; a < 3; ++a)
        if (frame.resolution[a] < 1 || frame.resolution[a] > kMaxFrameResolution) throw WireError("bad grid resolution");
    grid.bounds = frame.bounds;
    grid.resolution = frame.resolution;
    grid.cellWidth = frame.cellWidth;
    grid.inverseWidth = frame.inverseWidth;
    return grid;
}

void putCell(ByteWriter& output, const GridCell& cell) {
    for (int c : cell) output.put<int32_t>(c);
}

void runGridResolution(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const ResolutionCall& call : input.getVector<ResolutionCall>(kMaxCalls))
        putCell(output, gridResolution(call.bounds, call.primCount, call.options));
}

void runGridCell(ByteReader& input, ByteWriter& output, WorkerState&) {
    UniformGrid grid = gridOf(input.get<GridFrame>());
    for (const Vec3& p : input.getVector<Vec3>(kMaxCalls)) putCell(output, cellOfPoint(grid, p));
}

void runGridRange(ByteReader& input, ByteWriter& output, WorkerState&) {
    UniformGrid grid = gridOf(input.get<GridFrame>());
    for (const Bounds3f& box : input.getVector<Bounds3f>(kMaxCalls)) {
        CellRange range = cellRange(grid, box);
        putCell(output, range.lower);
        putCell(output, range.upper);
    }
}

void runDdaSetup(ByteReader& input, ByteWriter& output, WorkerState&) {
    UniformGrid grid = gridOf(input.get<GridFrame>());
    for (const DdaSetupCall& call : input.getVector<DdaSetupCall>(kMaxCalls))
        output.put(ddaSetup(grid, call.ray, call.tEnter, call.tExit));
}

void runDdaStep(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (DdaStepCall call : input.getVector<DdaStepCall>(kMaxCalls)) {
        bool inside = ddaStep(call.state, call.resolution);
        output.put<uint8_t>(inside ? 1 : 0);
        output.put(call.state);
    }
}

// The cells the student's own set-up and step visit, the first one included; a walk that does
// not end within kMaxWalkCells is cut there (the grader reports it as endless).
void runDdaWalk(ByteReader& input, ByteWriter& output, WorkerState&) {
    UniformGrid grid = gridOf(input.get<GridFrame>());
    for (const DdaSetupCall& call : input.getVector<DdaSetupCall>(kMaxCalls)) {
        std::vector<GridCell> cells;
        DdaState state = ddaSetup(grid, call.ray, call.tEnter, call.tExit);
        do cells.push_back(state.cell);
        while (cells.size() <= kMaxWalkCells && ddaStep(state, grid.resolution));
        output.put<uint32_t>(static_cast<uint32_t>(cells.size()));
        for (const GridCell& cell : cells) putCell(output, cell);
    }
}

void runGridBuild(ByteReader& input, ByteWriter& output, WorkerState& state) {
    state.scene = readScene(input);
    auto options = input.get<GridOptions>();
    if (!(options.cellsPerPrimitive >= 1.0 && options.cellsPerPrimitive <= 1000.0) || options.maxResolution < 1 ||
        options.maxResolution > kMaxFrameResolution)
        throw WireError("bad grid options");
    state.primitives = std::make_unique<PrimitiveSet>(state.scene);
    UniformGrid& grid = state.structure.emplace<UniformGrid>();  // queries after a build that threw see an empty grid
    grid = GridAdapter::build(*state.primitives, options, GridInsertion::Box);
    writeGrid(output, grid);
}

const TaskRegistration registration{{kTaskGridResolution, runGridResolution}, {kTaskGridCell, runGridCell},
                                    {kTaskGridRange, runGridRange},           {kTaskDdaSetup, runDdaSetup},
                                    {kTaskDdaStep, runDdaStep},               {kTaskDdaWalk, runDdaWalk},
                                    {kTaskGridBuild, runGridBuild},
                                    {kTaskGridQuery, runBuiltQuery<GridAdapter, UniformGrid>},
                                    {kTaskGridGivenQuery, runGivenQuery<GridAdapter, readGrid>}};

}  // namespace

}  // namespace rtlab::grader::worker
