// What `rtlab view SCENE` shows (docs/viewer.md#the-command), made into a CaseView: the
// structure an --accel name builds over the scene with the code this executable links, the
// given rays (or a pixel's camera ray and its shadow rays) traced through it with their
// traversal traces, the same rays through the exact oracle and, when rtlab-solution is built
// beside this executable, through the reference (its traces, read back with the validating
// decoder); for a pixel, the render, its traversal-cost heat map, the POV-Ray reference and the
// difference. The student's a3 DDA comes in as a function (DdaWalk), so this file names no
// assignment function: the viewer library stays linkable into rtlab-grader.
#pragma once

#include "framework/external/temporary_directory.h"
#include "framework/interface/grid.h"
#include "viewer/case_view.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtlab::viewer {

// The cells a3's ddaSetup and ddaStep walk for ray over [tEnter, tExit] (at most maxCells).
using DdaWalk = std::function<std::vector<GridCell>(const UniformGrid& grid, const Ray& ray, float tEnter, float tExit, size_t maxCells)>;

struct SceneCaseRequest {
    std::string scenePath;
    std::string acceleratorName;
    std::vector<Ray> rays;        // traced as closest-hit queries
    std::string rayLabel;         // for a single given ray: "ray 7 of rays.txt"
    std::optional<std::array<int, 2>> pixel;  // instead of rays: this pixel's camera ray and shadow rays
    int width = 0, height = 0;    // of the image (0: the reference's size, else 320 wide)
    std::string cameraName;
    std::filesystem::path repositoryDir;   // where scenes/refs lives
    std::filesystem::path referenceProgram;  // rtlab-solution, to trace the same rays; empty: none
    DdaWalk ddaWalk;              // the linked a3 DDA; empty: no DDA cells
    std::string pixelCommand;     // shown for a clicked pixel, with X,Y in it
};

struct SceneCase {
    std::unique_ptr<Scene> scene;  // the CaseView points into it
    CaseView view;
    std::unique_ptr<TemporaryDirectory> scratch;  // the PNGs the view's images name
    double loadSeconds = 0.0, buildSeconds = 0.0;  // the scene's loading, the structure's build
};

// Throws rtlab::Error for a bad accelerator name or scene, and NotImplemented from a stub that
// building needs (a stub the traversal needs becomes a note: the trace shows how far it got).
SceneCase buildSceneCase(const SceneCaseRequest& request);

// The reference's side: traces of rays through the named structure, written as trace-K.bin
// (traversal_trace_format.h) into outDir; rays from anyHitFrom on are any-hit queries.
void writeRayTraces(const std::string& scenePath, const std::string& acceleratorName, const std::vector<Ray>& rays, size_t anyHitFrom,
                    const std::filesystem::path& outDir);

}  // namespace rtlab::viewer
