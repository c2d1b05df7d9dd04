// Embree 3 (Debian's libembree-dev) as the peer, set up exactly as in
// docs/performance.md#embree-setup-and-mismatches: one triangle geometry with shared float3
// vertex and uint3 index buffers, scene and geometry build quality MEDIUM or HIGH,
// rtcIntersect1 (closest hit) or rtcOccluded1 (any hit) per ray.
#pragma once

#include "bench/bench_system.h"
#include "framework/scene/scene.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <string>

namespace rtlab::bench {

enum class EmbreeQuality { Medium, High };

class EmbreeSystem final : public BenchSystem {
public:
    // isa, if not empty, caps the kernels Embree picks at run time (its device setting isa=,
    // e.g. "avx2"); empty lets it take the best this CPU runs.
    EmbreeSystem(const Scene& scene, EmbreeQuality quality, std::string isa = {});
    ~EmbreeSystem() override;
    EmbreeSystem(const EmbreeSystem&) = delete;
    EmbreeSystem& operator=(const EmbreeSystem&) = delete;

    std::string label() const override;
    double build(int threads) override;
    void trace(std::span<const BenchRay> rays, TraceResult* results, TraversalStats& stats) const override;
    void occluded(std::span<const BenchSegment> rays, uint8_t* blocked, TraversalStats& stats) const override;
    bool buildsInParallel() const override { return true; }
    bool countsWork() const override { return false; }
    std::optional<double> sahCost() const override { return std::nullopt; }
    double bytesPerTriangle() const override { return bytesPerTriangle_; }
    std::optional<double> referencesPerTriangle() const override { return std::nullopt; }

private:
    void useDevice(int threads);

    const Scene& scene_;
    EmbreeQuality quality_;
    std::string isa_;
    int deviceThreads_ = 0;
    RTCDevice device_ = nullptr;
    RTCScene rtcScene_ = nullptr;
    std::atomic<int64_t> deviceBytes_{0};  // what the device has allocated, from its memory monitor
    double bytesPerTriangle_ = 0.0;
};

}  // namespace rtlab::bench
