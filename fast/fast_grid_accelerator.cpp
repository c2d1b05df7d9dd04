#include "fast/fast_grid_accelerator.h"

#include "fast/triangle_packet.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/grid/grid_structure_view.h"
#include "framework/interface/a3_grid.h"

#include <algorithm>
#include <span>
#include <utility>

namespace rtlab {
namespace {

// The new primitives of a cell, gathered four to a packet: a full packet is tested at once, a
// part-filled one when the cell is done. Spheres are tested on their own as they come.
class PacketQueue {
public:
    PacketQueue(const PrimitiveSet& primitives, const Ray& ray) : primitives_(primitives), ray_(ray), sheared_(ray) {}

    // Queues prim; true when something must be tested now: a full packet, or a sphere (tested
    // on its own while the triangles queued before it wait for their packet).
    bool add(uint32_t prim) {
        if (prim >= primitives_.triangleCount()) {
            sphere_ = prim;
            return true;
        }
        packet_.set(lanes_++, prim, primitives_.triangle(prim));
        return lanes_ == TrianglePacket::kLanes;
    }

    // Tests the sphere if one is queued, else the queued triangles: the closest hit in
    // (tMin, hit->t], or any hit in (tMin, tMax] when hit is null. Returns whether one was hit.
    bool test(Hit* hit) {
        if (sphere_ != kNoPrimitive) {
            Hit sphereHit;
            sphereHit.t = hit ? hit->t : ray_.tMax;
            uint32_t sphere = std::exchange(sphere_, kNoPrimitive);
            if (!primitives_.intersect(sphere, ray_, sphereHit)) return false;
            if (hit) *hit = sphereHit;
            return true;
        }
        if (lanes_ == 0) return false;
        const float tMax = hit ? hit->t : ray_.tMax;
        // Lanes left over from the previous packet hold triangles tested already.
        packet_.pad(lanes_, true);
        lanes_ = 0;
        if (!hit) return sheared_.anyHit(packet_, tMax);
        PacketHit nearest = sheared_.closest(packet_, tMax);
        if (nearest.lane < 0) return false;
        *hit = Hit{nearest.hit.t, packet_.prim[nearest.lane], nearest.hit.b1, nearest.hit.b2};
        return true;
    }

private:
    const PrimitiveSet& primitives_;
    const Ray& ray_;
    const ShearedRay sheared_;
    TrianglePacket packet_;
    int lanes_ = 0;
    uint32_t sphere_ = kNoPrimitive;
};

// The closest hit: a cell's hit is final once it lies no farther than where the ray leaves the
// cell (intersectGrid's rule, docs/a3-grid.md#traversal).
struct ClosestHit {
    PacketQueue queue;
    Hit hit;

    bool add(uint32_t prim) {
        if (queue.add(prim)) queue.test(&hit);
        return false;
    }
    bool cellDone(DdaState& state) {
        queue.test(&hit);
        float cellExit = std::min({state.tNext[0], state.tNext[1], state.tNext[2]});
        if (hit.t <= cellExit) return true;
        state.tExit = std::min(state.tExit, hit.t);
        return false;
    }
};

// Any hit: the first blocker ends the walk.
struct AnyHit {
    PacketQueue queue;
    bool found = false;

    bool add(uint32_t prim) { return queue.add(prim) && (found = queue.test(nullptr)); }
    bool cellDone(DdaState&) { return found = queue.test(nullptr); }
};

}  // namespace

void FastGridAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    frame_ = gridFrame(primitives.allBounds(), options_);
    cells_ = sortIntoCells(frame_, primitives.allBounds());
}

template <typename Query>
void FastGridAccelerator::walk(const Ray& ray, float tMax, TraversalStats& stats, Query& query) const {
    ++stats.rays;
    if (cells_.primIndices.empty()) return;
    ++stats.nodeVisits;
    float tEnter;
    if (!intersectBox(frame_.bounds, RayInverse(ray), ray.tMin, tMax, &tEnter)) return;
    DdaState state = ddaSetup(frame_, ray, tEnter, tMax);
    const uint32_t* lists = cells_.primIndices.data();
    std::span<const uint32_t> previous;
    uint64_t cells = 0, tests = 0, repeats = 0;
    bool done = false;
    do {
        ++cells;
        size_t c = frame_.cellIndex(state.cell);
        std::span<const uint32_t> current(lists + cells_.cellStart[c], lists + cells_.cellStart[c + 1]);
        // Both lists are sorted: one pointer through the previous cell's finds the repeats.
        const uint32_t* seen = previous.data();
        const uint32_t* seenEnd = seen + previous.size();
        for (uint32_t prim : current) {
            while (seen != seenEnd && *seen < prim) ++seen;
            if (seen != seenEnd && *seen == prim) {
                ++repeats;
                continue;
            }
            ++tests;
            if ((done = query.add(prim))) break;
        }
        if (done || (done = query.cellDone(state))) break;
        previous = current;
    } while (ddaStep(state, frame_.resolution));
    stats.cellSteps += cells;
    stats.primitiveTests += tests;
    stats.mailboxRepeats += repeats;
}

Hit FastGridAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    ClosestHit query{PacketQueue(*primitives_, ray), Hit{}};
    query.hit.t = ray.tMax;
    walk(ray, ray.tMax, stats, query);
    if (!query.hit.found()) query.hit.t = kInfinity;
    return query.hit;
}

bool FastGridAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    AnyHit query{PacketQueue(*primitives_, ray)};
    walk(ray, ray.tMax, stats, query);
    return query.found;
}

StructureView FastGridAccelerator::structure() const {
    return gridStructureView(frame_, cells_.cellStart, cells_.primIndices);
}

namespace {

AcceleratorType fastGridType() {
    // The grid's own options but its insertion: the tuned fill places primitives by their boxes.
    std::vector<AcceleratorOption> gridOptions;
    for (const AcceleratorOption& option : findAcceleratorType("grid")->options)
        if (option.key != "insert") gridOptions.push_back(option);
    return {"fastgrid",
            "the grid of a3, filled by a counting sort and walked with packets of four triangles (fast/)",
            gridOptions,
            [](const AcceleratorParameters& p) {
                GridOptions options;
                options.cellsPerPrimitive = p.number("C");
                options.maxResolution = p.integer("res");
                return std::make_unique<FastGridAccelerator>(options);
            },
            {"fastgrid"}};
}

const AcceleratorRegistration kFastGrid{fastGridType()};

}  // namespace
}  // namespace rtlab
