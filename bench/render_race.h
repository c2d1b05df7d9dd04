// The renderer against POV-Ray on the same image (docs/performance.md#the-renderer): the
// bunny at 784x784, one ray per pixel centre, on one thread. POV-Ray's side is the Trace Time
// it reports for the reference render of the exported scene; ours is Renderer::render with the
// fastest accelerator this executable has, built beforehand, as POV-Ray bounds before it
// traces. The same run measures how much of our render is spent beyond tracing, and checks that
// the image is the textbook structure's (the a1/a2 reference BVH's) to the bit.
#pragma once

#include "framework/verification/trace_share.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

struct RenderRaceOptions {
    std::string scene = "bunny";
    std::string modelsDir;
    int size = 784;   // width and height
    int repeats = 11;  // renders and replays (the best counts), and pairs of a POV-Ray run and a render
};

struct RenderRaceResult {
    RenderRaceOptions options;
    std::string accelerator;
    std::string povrayVersion;
    TraceShare share;               // our render and its queries alone
    double povTraceSeconds = 0.0;   // POV-Ray's Trace Time
    std::string loadAverage;
    std::string textbookAccelerator;  // the structure the image is compared with
    size_t differentPixels = 0;       // pixels whose colour differs in any bit from that render's

    std::vector<double> pairSpeedups;  // POV-Ray's time / ours, a POV-Ray run and a render of ours in turn

    // The best render against the best POV-Ray run.
    double speedup() const { return share.renderSeconds > 0.0 ? povTraceSeconds / share.renderSeconds : 0.0; }
    // The median of the pairs: the figure the verdict rests on.
    double pairedSpeedup() const;
};

// A smaller image for --quick.
RenderRaceOptions quickRenderRace(RenderRaceOptions options);

RenderRaceResult runRenderRace(const RenderRaceOptions& options);

// The figures and the targets: at least 8x POV-Ray's speed (the median of alternating pairs), at
// most 15 % beyond tracing, the textbook structure's image to the bit.
void writeRenderRaceMarkdown(std::ostream& out, const RenderRaceResult& result);

}  // namespace rtlab::bench
