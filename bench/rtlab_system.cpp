#include "bench/rtlab_system.h"

#include "framework/accel/accelerator_registry.h"
#include "framework/accel/bvh_accelerator.h"

#include <chrono>

namespace rtlab::bench {

AcceleratorSpec withMaxLeaf(const std::string& name, int maxLeaf) {
    AcceleratorSpec spec{name};
    setMaxLeaf(spec, maxLeaf);
    return spec;
}

std::string rtlabLabel(const AcceleratorSpec& spec) {
    std::string label = "rtlab:" + spec.name;
    if (const AcceleratorSpec::FlagSetting* leaf = spec.flagSetting("leaf"))
        label += ":L" + std::to_string(static_cast<int>(std::get<double>(leaf->value)));
    return label;
}

RtlabSystem::RtlabSystem(const PrimitiveSet& primitives, const AcceleratorSpec& spec)
    : primitives_(primitives), spec_(spec) {}

std::string RtlabSystem::label() const { return rtlabLabel(spec_); }

double RtlabSystem::build(int) {
    accelerator_ = makeAccelerator(spec_);  // a fresh accelerator per build
    auto start = std::chrono::steady_clock::now();
    accelerator_->build(primitives_);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void RtlabSystem::trace(std::span<const BenchRay> rays, TraceResult* results, TraversalStats& stats) const {
    const Accelerator& accelerator = *accelerator_;
    for (const BenchRay& bench : rays) {
        Ray ray;
        ray.origin = bench.origin;
        ray.direction = bench.direction;
        Hit hit = accelerator.intersect(ray, stats);
        *results++ = TraceResult{hit.t, hit.prim};
    }
}

void RtlabSystem::occluded(std::span<const BenchSegment> rays, uint8_t* blocked, TraversalStats& stats) const {
    const Accelerator& accelerator = *accelerator_;
    for (const BenchSegment& segment : rays) {
        Ray ray;
        ray.origin = segment.origin;
        ray.direction = segment.direction;
        ray.tMax = segment.tMax;
        *blocked++ = accelerator.occluded(ray, stats);
    }
}

bool RtlabSystem::buildsInParallel() const {
    // The structures whose builders take threads say so with a `threads` option.
    const AcceleratorType* type = findAcceleratorType(spec_.name.substr(0, spec_.name.find_first_of(":-")));
    return type && type->option("threads");
}

std::optional<double> RtlabSystem::sahCost() const {
    // The SAH cost of a tree: the BVHs (bvh, bvh4, bvh8, fastbvh) have one; brute force and grids do not.
    if (!spec_.name.starts_with("bvh") && !spec_.name.starts_with("fastbvh")) return std::nullopt;
    return rtlab::sahCost(accelerator_->structure());
}

std::optional<double> RtlabSystem::referencesPerTriangle() const {
    double triangles = std::max<uint32_t>(primitives_.size(), 1);
    return static_cast<double>(accelerator_->structure().primIndices.size()) / triangles;
}

double RtlabSystem::bytesPerTriangle() const {
    double triangles = std::max<uint32_t>(primitives_.size(), 1);
    return static_cast<double>(accelerator_->memoryBytes()) / triangles;
}

}  // namespace rtlab::bench
