// How much of a render is tracing (docs/performance.md#the-renderer): the render's time against
// the time its own accelerator queries take alone. The queries are recorded in one extra
// render, then traced again without shading, sampling or image writes; what the render spends
// beyond that is the renderer's own cost.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/render/renderer.h"

#include <cstddef>
#include <vector>

namespace rtlab {

struct TraceShare {
    double renderSeconds = 0.0;  // the best of the renders
    double traceSeconds = 0.0;   // the best of the replays of the same queries
    size_t queries = 0;          // closest-hit and any-hit queries of one render
    // (render - replay) / render of each pass, a render and the replay right after it.
    std::vector<double> passShares;

    // The renderer's share of its own time: (render - trace) / render, at least 0.
    double beyondTracing() const;
    // The median over the passes of their own shares: each render is compared with the replay
    // that ran next to it, so a stretch of slow machine slows both sides of one pair.
    double pairedBeyondTracing() const;
};

// Renders `repeats` times and traces the recorded queries `repeats` times on settings.threads
// threads; the best of each counts, as a benchmark's passes do.
TraceShare measureTraceShare(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                             RenderSettings settings, int repeats);

}  // namespace rtlab
