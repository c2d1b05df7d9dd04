// Traversal traces (framework/interface/traversal_trace.h): recorded in order by the Traversal
// context when asked and only then, capped, encoded and decoded by a reader that refuses every
// malformed or forged byte string (framework/accel/traversal_trace_format.h).
#include "framework/accel/accelerator.h"
#include "framework/accel/primitive_set.h"
#include "framework/accel/traversal_trace_format.h"
#include "framework/core/pcg32.h"
#include "framework/scene/gltf_loader.h"

#include <doctest/doctest.h>

#include <cstring>

namespace rtlab {
namespace {

Scene cornellBox() { return loadGltf(std::string(RTLAB_SOURCE_DIR) + "/scenes/cornell-box.gltf"); }

struct Built {
    Scene scene = cornellBox();
    PrimitiveSet primitives{scene};
    std::unique_ptr<Accelerator> accelerator;

    explicit Built(const std::string& name) {
        AcceleratorSpec spec;
        spec.name = name;
        accelerator = makeAccelerator(spec);
        accelerator->build(primitives);
    }
};

const Ray kRay{Vec3(0.1f, 1.2f, 3.5f), Vec3(0.03f, -0.11f, -1.0f)};

size_t countOf(const TraversalTrace& trace, TraceOpKind kind) {
    size_t n = 0;
    for (const TraceOp& op : trace.ops) n += op.kind == kind;
    return n;
}

}  // namespace

TEST_CASE("a trace lists every counted operation in order, for every framework structure") {
    for (const char* name : {"brute", "bvh", "bvh-median", "grid", "grid2", "octree", "kdtree", "bsp"}) {
        CAPTURE(name);
        Built b(name);
        TraversalTrace trace;
        TraversalStats stats;
        stats.trace = &trace;
        Hit hit = b.accelerator->intersect(kRay, stats);
        REQUIRE(hit.found());
        CHECK(countOf(trace, TraceOpKind::BoxTest) == stats.nodeVisits);
        CHECK(countOf(trace, TraceOpKind::CellStep) + countOf(trace, TraceOpKind::LeafEntry) == stats.cellSteps);
        CHECK(countOf(trace, TraceOpKind::PlaneStep) == stats.planeSteps);
        CHECK(countOf(trace, TraceOpKind::PrimitiveTest) == stats.primitiveTests);
        CHECK(countOf(trace, TraceOpKind::MailboxRepeat) == stats.mailboxRepeats);
        CHECK(trace.boxes.size() == stats.nodeVisits);
        CHECK(trace.dropped == 0);
        // The hit is the last primitive test that hit, at the answer's t.
        const TraceOp* last = nullptr;
        for (const TraceOp& op : trace.ops)
            if (op.kind == TraceOpKind::PrimitiveTest && op.hit) last = &op;
        REQUIRE(last != nullptr);
        CHECK(last->index == hit.prim);
        CHECK(last->t == hit.t);
        // Any-hit queries are traced too.
        TraversalTrace shadow;
        TraversalStats shadowStats;
        shadowStats.trace = &shadow;
        CHECK(b.accelerator->occluded(kRay, shadowStats));
        CHECK(countOf(shadow, TraceOpKind::PrimitiveTest) == shadowStats.primitiveTests);
    }
}

TEST_CASE("no trace unless asked, and a full trace counts what it drops") {
    Built b("brute");
    TraversalStats stats;
    b.accelerator->intersect(kRay, stats);
    CHECK(stats.trace == nullptr);

    TraversalTrace trace;
    trace.capacity = 5;
    TraversalStats capped;
    capped.trace = &trace;
    b.accelerator->intersect(kRay, capped);
    CHECK(trace.ops.size() == 5);
    CHECK(trace.dropped == capped.primitiveTests - 5);
    CHECK(trace.truncated());
}

TEST_CASE("a trace survives its bytes, and a box test keeps its box") {
    Built b("bvh");
    TraversalTrace trace;
    TraversalStats stats;
    stats.trace = &trace;
    b.accelerator->intersect(kRay, stats);
    trace.dropped = 3;
    std::vector<uint8_t> bytes = encodeTraversalTrace(trace);
    TraversalTrace back = decodeTraversalTrace(bytes);
    REQUIRE(back.ops.size() == trace.ops.size());
    CHECK(std::memcmp(back.ops.data(), trace.ops.data(), trace.ops.size() * sizeof(TraceOp)) == 0);
    REQUIRE(back.boxes.size() == trace.boxes.size());
    CHECK(std::memcmp(back.boxes.data(), trace.boxes.data(), trace.boxes.size() * sizeof(Bounds3f)) == 0);
    CHECK(back.dropped == 3);
    CHECK(trace.boxes[0].lower == b.accelerator->structure().nodes[0].bounds.lower);
}

TEST_CASE("the decoder refuses malformed and forged traces") {
    TraversalTrace trace;
    trace.addBox(Bounds3f(Vec3(0.0f), Vec3(1.0f)), true, 0.5f, 2.0f);
    trace.add(TraceOp{TraceOpKind::PrimitiveTest, 1, 0, 7, 1.0f, 2.0f});
    trace.add(TraceOp{TraceOpKind::CellStep});
    const std::vector<uint8_t> good = encodeTraversalTrace(trace);
    CHECK_NOTHROW(decodeTraversalTrace(good));

    auto corrupt = [&](size_t at, uint8_t value) {
        std::vector<uint8_t> bad = good;
        bad[at] = value;
        return bad;
    };
    auto refuses = [](const std::vector<uint8_t>& bytes, const char* what) {
        CAPTURE(what);
        CHECK_THROWS_AS(decodeTraversalTrace(bytes), TraceFormatError);
    };
    refuses({}, "empty");
    refuses(std::vector<uint8_t>(good.begin(), good.end() - 1), "one byte short");
    std::vector<uint8_t> longer = good;
    longer.push_back(0);
    refuses(longer, "a byte too many");
    refuses(corrupt(0, 'x'), "wrong magic");
    refuses(corrupt(4, 9), "unknown version");
    refuses(corrupt(8, 0xff), "an op count the bytes do not hold");
    refuses(corrupt(12, 2), "more boxes than box tests");
    size_t op = kTraceHeaderBytes;
    refuses(corrupt(op, 6), "an unknown kind");
    refuses(corrupt(op + 1, 2), "a hit flag of 2");
    refuses(corrupt(op + 4, 1), "a box test naming the wrong box");
    refuses(corrupt(op + 16 + 2, 1), "a reserved field set");
    refuses(corrupt(op + 32 + 1, 1), "a hit flag on a cell step");
    refuses(corrupt(op + 32 + 4, 0), "an index on a cell step");

    // A header that promises 2^32 - 1 operations is refused before anything is allocated.
    std::vector<uint8_t> forged = good;
    uint32_t huge = 0xffffffffu;
    std::memcpy(forged.data() + 8, &huge, 4);
    refuses(forged, "a forged length");
    CHECK_THROWS_AS(decodeTraversalTrace(good, 2), TraceFormatError);  // over the caller's cap

    // Random bytes behind a valid header never crash the reader.
    Pcg32 rng(25, 1);
    for (int round = 0; round < 2000; ++round) {
        std::vector<uint8_t> noise = good;
        for (int k = 0; k < 4; ++k) noise[rng.next() % noise.size()] = static_cast<uint8_t>(rng.next());
        try {
            TraversalTrace t = decodeTraversalTrace(noise);
            // What passes keeps the rules: the boxes match the box tests.
            CHECK(countOf(t, TraceOpKind::BoxTest) == t.boxes.size());
        } catch (const TraceFormatError&) {
        }
    }
}

}  // namespace rtlab
