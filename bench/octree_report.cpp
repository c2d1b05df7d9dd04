// The octree's part of the bench report (docs/performance.md#octrees): its memory target (at most
// 20 references per triangle on the engine, where bounding-box insertion stores 153) and the
// same figure for every octree row measured; nothing when no octree row was measured.
#include "bench/target_tables.h"

#include <cstdio>
#include <string>

namespace rtlab::bench {
namespace {

constexpr const char* kOctree = "rtlab:octree";
// issue 14: exact insertion keeps the engine's long thin triangles out of the leaves their
// boxes overlap but their surfaces do not.
constexpr double kEngineReferencesTarget = 20.0;

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

void writeOctreeTargets(std::ostream& out, const std::vector<ThroughputRecord>& records) {
    std::string lines;
    for (const ThroughputRecord& r : records) {
        if (!r.system.starts_with(kOctree) || r.rays != RayKind::Primary || r.threads != 1 || !r.measured || !r.referencesPerTriangle)
            continue;
        std::string figure = number(*r.referencesPerTriangle) + " references per triangle, " +
                             (r.primitiveTestsPerRay ? number(*r.primitiveTestsPerRay) : std::string("?")) + " triangle tests per primary ray";
        if (r.scene == "engine" && r.system == kOctree)
            figure += " (target <= " + number(kEngineReferencesTarget) + ": " +
                      (*r.referencesPerTriangle <= kEngineReferencesTarget ? "met" : "**not met**") + ")";
        lines += "| " + r.scene + " | " + r.system.substr(6) + " | " + figure + " |\n";
    }
    if (lines.empty()) return;
    out << "\n### Octree memory, single thread, primary rays\n\n| scene | system | figure |\n|---|---|---|\n" << lines;
}

const TargetTableRegistration registration{"octree", writeOctreeTargets};

}  // namespace
}  // namespace rtlab::bench
