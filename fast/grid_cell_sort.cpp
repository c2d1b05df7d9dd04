#include "fast/grid_cell_sort.h"

#include "framework/core/error.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace rtlab {
namespace {

// a3's cellOfPoint along one axis, with the same float arithmetic. Its floor is left out: the
// clamp lets only offsets of at least 1 through to the cast, and truncating a positive number
// is flooring it (a NaN offset fails both comparisons and lands in cell 0, as there).
struct AxisCells {
    float lower = 0.0f, inverseWidth = 0.0f;
    int last = 0;

    uint32_t operator()(float p) const {
        float offset = (p - lower) * inverseWidth;
        return offset >= float(last) ? uint32_t(last) : offset > 0.0f ? uint32_t(offset) : 0u;
    }
};

// The cells of one primitive's box (a3's cellRange), lower[a] .. lower[a] + span[a] on each
// axis. A box that is not isPlaceable spans no layer: span[2] = kNowhere.
struct BoxCells {
    static constexpr uint16_t kNowhere = 0xffff;  // no grid has that many cells along an axis
    uint16_t lower[3];
    uint16_t span[3];

    // At most two cells along every axis: the usual case when cells are about a primitive's
    // size, as the resolution rule makes them. Such boxes take the branch-free path below.
    bool small() const { return (span[0] | span[1] | span[2]) <= 1; }
};

// Each layer's run of dealt references has one slot of slack after it: the branch-free path
// writes a box's candidate cells unconditionally and advances only past the real ones, so its
// last write can land one past the run's end. A last run, for layer `layers`, takes the writes
// of boxes in the top layer towards a layer above that does not exist.
constexpr size_t kSlack = 1;

// Step 1: every box's cells, and how many references each z layer gets (the box's x-y
// footprint in each layer it spans; entry `layers` stays 0).
std::vector<size_t> layerCounts(const UniformGrid& frame, std::span<const Bounds3f> primBounds,
                                UninitialisedVector<BoxCells>& boxes) {
    AxisCells axes[3];
    for (int a = 0; a < 3; ++a) axes[a] = {frame.bounds.lower[a], frame.inverseWidth[a], frame.resolution[a] - 1};
    std::vector<size_t> count(size_t(frame.resolution[2]) + 1, 0);
    boxes.resize(primBounds.size());
    for (size_t prim = 0; prim < primBounds.size(); ++prim) {
        const Bounds3f& box = primBounds[prim];
        BoxCells& cells = boxes[prim];
        if (!isPlaceable(box)) {
            cells = {{0, 0, 0}, {0, 0, BoxCells::kNowhere}};
            continue;
        }
        for (int a = 0; a < 3; ++a) {
            uint32_t lower = axes[a](box.lower[a]);
            cells.lower[a] = static_cast<uint16_t>(lower);
            cells.span[a] = static_cast<uint16_t>(axes[a](box.upper[a]) - lower);
        }
        size_t footprint = size_t(cells.span[0] + 1) * size_t(cells.span[1] + 1);
        if (cells.small()) {
            count[cells.lower[2]] += footprint;
            count[cells.lower[2] + 1] += footprint * cells.span[2];
        } else {
            for (uint32_t z = 0; z <= cells.span[2]; ++z) count[cells.lower[2] + z] += footprint;
        }
    }
    return count;
}

// Steps 2 and 3 for references packed into one word: the cell's index within its layer in the
// high bits, the primitive in the low `primBits` bits. A word of 32 bits halves the memory
// both steps stream through whenever the layer and the primitive count allow it.
template <typename Word>
GridCells dealAndScatter(const UniformGrid& frame, const UninitialisedVector<BoxCells>& boxes,
                         const std::vector<size_t>& layerCount, int primBits) {
    const uint32_t rowCells = uint32_t(frame.resolution[0]);
    const size_t layerCells = size_t(rowCells) * size_t(frame.resolution[1]);
    const size_t layers = size_t(frame.resolution[2]);
    const Word primMask = (Word(1) << primBits) - 1;
    std::vector<size_t> runStart(layers + 2, 0);
    for (size_t z = 0; z <= layers; ++z) runStart[z + 1] = runStart[z] + layerCount[z] + kSlack;

    // 2. Deal the references into their layers' runs. Each run is written front to back, so
    //    the writes stream through memory; primitives go in index order, so each run is sorted.
    UninitialisedVector<Word> dealt(runStart.back());
    std::vector<Word*> cursor(layers + 1);
    for (size_t z = 0; z <= layers; ++z) cursor[z] = dealt.data() + runStart[z];
    for (uint32_t prim = 0; prim < boxes.size(); ++prim) {
        const BoxCells& cells = boxes[prim];
        if (cells.span[2] == BoxCells::kNowhere) continue;
        const Word corner = Word(cells.lower[1] * rowCells + cells.lower[0]) << primBits | prim;
        const Word nextColumn = Word(1) << primBits, nextRow = Word(rowCells) << primBits;
        if (cells.small()) {
            // The four cells of a 2 x 2 footprint in its layer and the one above, each written
            // where the next reference goes and kept by advancing past it only if it is real.
            const uint32_t sx = cells.span[0], sy = cells.span[1], sz = cells.span[2];
            for (uint32_t dz = 0; dz < 2; ++dz) {
                Word*& out = cursor[cells.lower[2] + dz];
                const uint32_t inLayer = dz == 0 ? 1u : sz;
                *out = corner;
                out += inLayer;
                *out = corner + nextColumn;
                out += inLayer & sx;
                *out = corner + nextRow;
                out += inLayer & sy;
                *out = corner + nextRow + nextColumn;
                out += inLayer & sx & sy;
            }
            continue;
        }
        for (uint32_t dz = 0; dz <= cells.span[2]; ++dz) {
            Word*& out = cursor[cells.lower[2] + dz];
            for (uint32_t dy = 0; dy <= cells.span[1]; ++dy)
                for (uint32_t dx = 0; dx <= cells.span[0]; ++dx) *out++ = corner + dy * nextRow + dx * nextColumn;
        }
    }

    // 3. Each layer on its own, as the textbook fills the whole grid: count its cells, turn
    //    the counts into start offsets, scatter. The layer's run is copied aside first, small
    //    enough to stay in cache with its counters and its part of the lists. With 32-bit words
    //    the lists are written over the dealt runs themselves: layer z's list starts z slack
    //    slots before its run and ends before the next run, so it overwrites only runs already
    //    copied aside, and the grid needs no second array of references.
    GridCells grid;
    grid.cellStart.resize(frame.cellCount() + 1);
    const size_t references = runStart[layers] - layers * kSlack;
    const Word* runs = dealt.data();
    if constexpr (std::is_same_v<Word, uint32_t>)
        grid.primIndices = std::move(dealt);  // the buffer moves with it: `runs` stays valid
    else
        grid.primIndices.resize(references);
    uint32_t* lists = grid.primIndices.data();
    std::vector<uint32_t> next(layerCells);
    std::vector<Word> run;
    uint32_t offset = 0;
    for (size_t z = 0; z < layers; ++z) {
        run.assign(runs + runStart[z], runs + runStart[z] + layerCount[z]);
        std::fill(next.begin(), next.end(), 0u);
        for (Word r : run) ++next[r >> primBits];
        uint32_t* start = grid.cellStart.data() + z * layerCells;
        for (size_t c = 0; c < layerCells; ++c) {
            uint32_t count = next[c];
            start[c] = next[c] = offset;
            offset += count;
        }
        for (Word r : run) lists[next[r >> primBits]++] = uint32_t(r & primMask);
    }
    grid.primIndices.resize(references);
    grid.cellStart.back() = offset;
    return grid;
}

}  // namespace

GridCells sortIntoCells(const UniformGrid& frame, std::span<const Bounds3f> primBounds) {
    UninitialisedVector<BoxCells> boxes;
    std::vector<size_t> layerCount = layerCounts(frame, primBounds, boxes);
    size_t references = 0;
    for (size_t count : layerCount) references += count;
    if (references > std::numeric_limits<uint32_t>::max())
        throw Error("the grid would hold " + std::to_string(references) + " references, more than its 32-bit offsets address");
    const size_t layerCells = size_t(frame.resolution[0]) * size_t(frame.resolution[1]);
    // Bits for the largest primitive index and the largest cell index within a layer.
    const int primBits = std::max(1, int(std::bit_width(std::max<size_t>(primBounds.size(), 1) - 1)));
    const int cellBits = int(std::bit_width(layerCells - 1));
    if (primBits < 32 && primBits + cellBits <= 32) return dealAndScatter<uint32_t>(frame, boxes, layerCount, primBits);
    return dealAndScatter<uint64_t>(frame, boxes, layerCount, 32);
}

}  // namespace rtlab
