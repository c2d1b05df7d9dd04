#include "framework/verification/trace_share.h"

#include "framework/core/error.h"
#include "framework/render/tiles.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <vector>

namespace rtlab {
namespace {

struct Query {
    Ray ray;
    bool anyHit;
    const PointQueries* queries;  // what answered it: these, or (null) the accelerator
};

class QueryLog {
public:
    void record(const Ray& ray, bool anyHit, const PointQueries* queries) {
        std::lock_guard lock(mutex_);
        queries_.push_back({ray, anyHit, queries});
    }
    std::vector<Query> take() { return std::move(queries_); }

private:
    std::mutex mutex_;
    std::vector<Query> queries_;
};

// Point queries that answer through the accelerator's own and write down every query.
class RecordingQueries : public PointQueries {
public:
    RecordingQueries(std::unique_ptr<PointQueries> inner, QueryLog& log) : inner_(std::move(inner)), log_(log) {}
    Hit intersect(const Ray& ray, TraversalStats& stats) const override {
        log_.record(ray, false, inner_.get());
        return inner_->intersect(ray, stats);
    }
    bool occluded(const Ray& ray, TraversalStats& stats) const override {
        log_.record(ray, true, inner_.get());
        return inner_->occluded(ray, stats);
    }

private:
    std::unique_ptr<PointQueries> inner_;
    QueryLog& log_;
};

// An accelerator that answers through a built one and writes down every query, those its
// point queries answer included.
class RecordingAccelerator : public Accelerator {
public:
    RecordingAccelerator(const Accelerator& inner, QueryLog& log) : inner_(inner), log_(log) {}

    void build(const PrimitiveSet&) override { throw Error("RecordingAccelerator: records a built accelerator"); }
    Hit intersect(const Ray& ray, TraversalStats& stats) const override {
        log_.record(ray, false, nullptr);
        return inner_.intersect(ray, stats);
    }
    bool occluded(const Ray& ray, TraversalStats& stats) const override {
        log_.record(ray, true, nullptr);
        return inner_.occluded(ray, stats);
    }
    std::unique_ptr<PointQueries> queriesAt(const Vec3& point) const override {
        std::unique_ptr<PointQueries> inner = inner_.queriesAt(point);
        if (!inner) return nullptr;
        return std::make_unique<RecordingQueries>(std::move(inner), log_);
    }
    StructureView structure() const override { return inner_.structure(); }
    size_t memoryBytes() const override { return inner_.memoryBytes(); }

private:
    const Accelerator& inner_;
    QueryLog& log_;
};

// Traces the queries in chunks of consecutive ones, as the renderer's tiles hand out its rays.
double traceSeconds(const Accelerator& accelerator, const std::vector<Query>& queries, int threads) {
    constexpr size_t kChunk = 4096;
    size_t chunks = (queries.size() + kChunk - 1) / kChunk;
    std::vector<TraversalStats> stats(chunks);
    auto start = std::chrono::steady_clock::now();
    parallelFor(chunks, threads, [&](size_t chunk) {
        size_t end = std::min(queries.size(), (chunk + 1) * kChunk);
        for (size_t i = chunk * kChunk; i < end; ++i) {
            const Query& query = queries[i];
            if (query.queries && query.anyHit)
                query.queries->occluded(query.ray, stats[chunk]);
            else if (query.queries)
                query.queries->intersect(query.ray, stats[chunk]);
            else if (query.anyHit)
                accelerator.occluded(query.ray, stats[chunk]);
            else
                accelerator.intersect(query.ray, stats[chunk]);
        }
    });
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

namespace {

double shareOf(double render, double trace) { return render > 0.0 ? std::max(0.0, (render - trace) / render) : 0.0; }

}  // namespace

double TraceShare::beyondTracing() const { return shareOf(renderSeconds, traceSeconds); }

double TraceShare::pairedBeyondTracing() const {
    if (passShares.empty()) return beyondTracing();
    std::vector<double> shares = passShares;
    std::sort(shares.begin(), shares.end());
    size_t middle = shares.size() / 2;
    return shares.size() % 2 ? shares[middle] : 0.5 * (shares[middle - 1] + shares[middle]);
}

TraceShare measureTraceShare(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                             RenderSettings settings, int repeats) {
    settings.progress = false;
    settings.aovs.clear();
    // One thread records the queries in the order one thread renders them; the image, and so
    // the set of queries, is the same for every thread count.
    RenderSettings recording = settings;
    recording.threads = 1;
    QueryLog log;
    RecordingAccelerator recorder(accelerator, log);
    // Kept: it holds the point queries the queries it recorded are traced with again.
    const Renderer recordingRenderer(scene, camera, recorder);
    recordingRenderer.render(recording);
    std::vector<Query> queries = log.take();

    TraceShare share;
    share.queries = queries.size();
    share.renderSeconds = share.traceSeconds = kInfinity;
    Renderer renderer(scene, camera, accelerator);
    for (int pass = 0; pass < std::max(1, repeats); ++pass) {
        double render = renderer.render(settings).seconds;
        double trace = traceSeconds(accelerator, queries, settings.threads);
        share.renderSeconds = std::min(share.renderSeconds, render);
        share.traceSeconds = std::min(share.traceSeconds, trace);
        share.passShares.push_back(shareOf(render, trace));
    }
    return share;
}

}  // namespace rtlab
