// The benchmark scenes by name (docs/performance.md#scene-definitions): bunny and engine from
// the models scripts/fetch-models prepares, sphereflake and randsoup generated, stadium (the
// bunny in a box of side 200); any other argument is read as a glTF path.
#pragma once

#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::bench {

// The default --scenes of a full run; randsoup is the optional stress case.
const std::vector<std::string>& defaultSceneNames();

// modelsDir holds bunny.gltf (scripts/fetch-models). Throws rtlab::Error naming the missing
// file and the command that makes it.
Scene loadBenchScene(const std::string& name, const std::string& modelsDir);

// The box the benchmark's cameras and ray origins are made from: the scene's bounds, except for
// the stadium, whose rays aim at the model inside (as the anchors' harness did).
Bounds3f benchRayBounds(const std::string& name, const Scene& scene);

}  // namespace rtlab::bench
