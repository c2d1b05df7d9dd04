#include "bench/embree_system.h"

#include "framework/core/error.h"

#include <chrono>
#include <cstring>
#include <string>
#include <utility>

namespace rtlab::bench {

EmbreeSystem::EmbreeSystem(const Scene& scene, EmbreeQuality quality, std::string isa)
    : scene_(scene), quality_(quality), isa_(std::move(isa)) {}

EmbreeSystem::~EmbreeSystem() {
    if (rtcScene_) rtcReleaseScene(rtcScene_);
    if (device_) rtcReleaseDevice(device_);
}

std::string EmbreeSystem::label() const {
    return quality_ == EmbreeQuality::Medium ? "embree:medium" : "embree:high";
}

void EmbreeSystem::useDevice(int threads) {
    if (device_ && deviceThreads_ == threads) return;
    if (rtcScene_) rtcReleaseScene(rtcScene_);
    rtcScene_ = nullptr;
    if (device_) rtcReleaseDevice(device_);
    std::string config = "threads=" + std::to_string(threads) + ",set_affinity=0";
    if (!isa_.empty()) config += ",isa=" + isa_;
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw Error("embree: rtcNewDevice(\"" + config + "\") failed");
    deviceThreads_ = threads;
    deviceBytes_ = 0;
    rtcSetDeviceMemoryMonitorFunction(
        device_,
        [](void* user, ssize_t bytes, bool) {
            static_cast<EmbreeSystem*>(user)->deviceBytes_ += bytes;
            return true;
        },
        this);
}

double EmbreeSystem::build(int threads) {
    useDevice(threads);
    if (rtcScene_) rtcReleaseScene(rtcScene_);  // a fresh scene per build
    RTCBuildQuality quality = quality_ == EmbreeQuality::Medium ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH;
    rtcScene_ = rtcNewScene(device_);
    rtcSetSceneFlags(rtcScene_, RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(rtcScene_, quality);

    const Triangles& triangles = scene_.triangles;
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, quality);
    void* vertices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3),
                                             triangles.positions.size());
    std::memcpy(vertices, triangles.positions.data(), triangles.positions.size() * sizeof(Vec3));
    void* indices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(uint32_t), triangles.indices.size());
    std::memcpy(indices, triangles.indices.data(), triangles.indices.size() * 3 * sizeof(uint32_t));
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(rtcScene_, geometry);
    rtcReleaseGeometry(geometry);

    int64_t before = deviceBytes_;
    auto start = std::chrono::steady_clock::now();
    rtcCommitScene(rtcScene_);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw Error("embree: rtcCommitScene failed");
    bytesPerTriangle_ = static_cast<double>(deviceBytes_ - before) / std::max<size_t>(triangles.indices.size(), 1);
    return ms;
}

void EmbreeSystem::trace(std::span<const BenchRay> rays, TraceResult* results, TraversalStats& stats) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (const BenchRay& ray : rays) {
        RTCRayHit query;
        query.ray.org_x = ray.origin.x;
        query.ray.org_y = ray.origin.y;
        query.ray.org_z = ray.origin.z;
        query.ray.tnear = 0.0f;
        query.ray.dir_x = ray.direction.x;
        query.ray.dir_y = ray.direction.y;
        query.ray.dir_z = ray.direction.z;
        query.ray.time = 0.0f;
        query.ray.tfar = kInfinity;
        query.ray.mask = ~0u;
        query.ray.id = 0;
        query.ray.flags = 0;
        query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(rtcScene_, &context, &query);
        bool found = query.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        *results++ = found ? TraceResult{query.ray.tfar, query.hit.primID} : TraceResult{};
    }
    stats.rays += rays.size();
}

void EmbreeSystem::occluded(std::span<const BenchSegment> rays, uint8_t* blocked, TraversalStats& stats) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (const BenchSegment& segment : rays) {
        RTCRay query;
        query.org_x = segment.origin.x;
        query.org_y = segment.origin.y;
        query.org_z = segment.origin.z;
        query.tnear = 0.0f;
        query.dir_x = segment.direction.x;
        query.dir_y = segment.direction.y;
        query.dir_z = segment.direction.z;
        query.time = 0.0f;
        query.tfar = segment.tMax;
        query.mask = ~0u;
        query.id = 0;
        query.flags = 0;
        rtcOccluded1(rtcScene_, &context, &query);
        *blocked++ = query.tfar < 0.0f;  // Embree sets tfar to -inf when something blocks the ray
    }
    stats.rays += rays.size();
}

}  // namespace rtlab::bench
