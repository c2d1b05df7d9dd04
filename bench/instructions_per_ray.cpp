// rtlab-solution-ir: the CI regression guard's probe (docs/performance.md, "Instructions per
// ray"). Builds each named accelerator over a scene, then traces every 16th benchmark ray with
// callgrind instrumentation switched on around the tracing loop only, and dumps one callgrind
// profile per accelerator and ray set. bench/check-instructions-per-ray runs it under
// `valgrind --tool=callgrind --instr-atstart=no` and divides the instruction counts by the
// number of rays. Outside valgrind the client requests do nothing.
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
                std::printf("%s: %zu rays, %zu hits\n", label.c_str(), rays.size(), found);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
        return 1;
    }
    return 0;
}
