// rtlab-solution-ir: the CI regression guard's probe (docs/performance.md, "Instructions per
// ray"). Builds each named accelerator over a scene, then traces every 16th benchmark ray with
// callgrind instrumentation switched on around the tracing loop only, and dumps one callgrind
// profile per accelerator and ray set: closest hits of the primary and incoherent rays, any hits
// of the shadow rays made from the primary rays' hits (bench/shadow_rays.h). bench/check-instructions-per-ray runs it under
// `valgrind --tool=callgrind --instr-atstart=no` and divides the instruction counts by the
// number of rays. Outside valgrind the client requests do nothing.
#include "bench/shadow_rays.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/primitive_set.h"
#include "framework/scene/benchmark_rays.h"
#include "framework/scene/benchmark_scenes.h"

#include <valgrind/callgrind.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

constexpr size_t kRayStride = 16;

struct StoredHit {
    float t;
    uint32_t prim;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s SCENE ACCEL...   (SCENE: glTF path, sphereflake or randsoup)\n", argv[0]);
        return 2;
    }
    try {
        Scene scene = loadOrGenerateScene(argv[1]);
        PrimitiveSet primitives(scene);
        for (int a = 2; a < argc; ++a) {
            AcceleratorSpec spec;
            spec.name = argv[a];
            std::unique_ptr<Accelerator> accelerator = makeAccelerator(spec);
            accelerator->build(primitives);
            std::vector<bench::BenchRay> primary;
            std::vector<bench::TraceResult> primaryHits;
            for (RayKind kind : {RayKind::Primary, RayKind::Incoherent}) {
                std::vector<Ray> all = makeBenchmarkRays(kind, scene.bounds());
                std::vector<Ray> rays;
                for (size_t i = 0; i < all.size(); i += kRayStride) rays.push_back(all[i]);
                std::vector<StoredHit> hits(rays.size());
                TraversalStats stats;
                std::string label = spec.name + "/" + rayKindName(kind) + "/" + std::to_string(rays.size());
                CALLGRIND_START_INSTRUMENTATION;
                CALLGRIND_ZERO_STATS;
                for (size_t i = 0; i < rays.size(); ++i) {
                    Hit hit = accelerator->intersect(rays[i], stats);
                    hits[i] = {hit.t, hit.prim};
                }
                CALLGRIND_DUMP_STATS_AT(label.c_str());
                CALLGRIND_STOP_INSTRUMENTATION;
                size_t found = 0;
                for (const StoredHit& h : hits) found += h.prim != kNoHit;
                std::printf("%s: %zu rays, %zu hits, per ray %.2f node visits and %.2f primitive tests\n", label.c_str(),
                            rays.size(), found, double(stats.nodeVisits) / rays.size(), double(stats.primitiveTests) / rays.size());
                if (kind == RayKind::Primary)
                    for (size_t i = 0; i < rays.size(); ++i) {
                        primary.push_back({rays[i].origin, rays[i].direction});
                        primaryHits.push_back({hits[i].t, hits[i].prim});
                    }
            }
            std::vector<bench::BenchSegment> shadow = makeShadowRays(primary, primaryHits, scene.bounds());
            std::vector<uint8_t> blocked(shadow.size());
            TraversalStats stats;
            std::string label = spec.name + "/shadow/" + std::to_string(shadow.size());
            CALLGRIND_START_INSTRUMENTATION;
            CALLGRIND_ZERO_STATS;
            for (size_t i = 0; i < shadow.size(); ++i) {
                Ray ray{shadow[i].origin, shadow[i].direction, 0.0f, shadow[i].tMax};
                blocked[i] = accelerator->occluded(ray, stats);
            }
            CALLGRIND_DUMP_STATS_AT(label.c_str());
            CALLGRIND_STOP_INSTRUMENTATION;
            size_t count = 0;
            for (uint8_t b : blocked) count += b;
            std::printf("%s: %zu rays, %zu blocked, per ray %.2f node visits and %.2f primitive tests\n", label.c_str(),
                        shadow.size(), count, double(stats.nodeVisits) / shadow.size(),
                        double(stats.primitiveTests) / shadow.size());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
        return 1;
    }
    return 0;
}
