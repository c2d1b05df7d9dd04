// The renderer against POV-Ray on the same image (docs/performance.md#the-renderer): the
// bunny at 784x784, one ray per pixel centre, on one thread. POV-Ray's side is the Trace Time
// it reports for the reference render of the exported scene; ours is Renderer::render with the
// fastest accelerator this executable has, built beforehand, as POV-Ray bounds before it
// traces. The same run measures how much of our render is spent beyond tracing.
#pragma once

#include "framework/verification/trace_share.h"

#include <ostream>
#include <string>

namespace rtlab::bench {

struct RenderRaceOptions {
    std::string scene = "bunny";
    std::string modelsDir;
    int size = 784;   // width and height
    int repeats = 11;  // the best of this many renders, replays and POV-Ray runs counts
};

struct RenderRaceResult {
    RenderRaceOptions options;
    std::string accelerator;
    std::string povrayVersion;
    TraceShare share;               // our render and its queries alone
    double povTraceSeconds = 0.0;   // POV-Ray's Trace Time
    std::string loadAverage;

    double speedup() const { return share.renderSeconds > 0.0 ? povTraceSeconds / share.renderSeconds : 0.0; }
};

// A smaller image for --quick.
RenderRaceOptions quickRenderRace(RenderRaceOptions options);

RenderRaceResult runRenderRace(const RenderRaceOptions& options);

// The figures and the two targets: at least 3x POV-Ray's speed, at most 15 % beyond tracing.
void writeRenderRaceMarkdown(std::ostream& out, const RenderRaceResult& result);

}  // namespace rtlab::bench
