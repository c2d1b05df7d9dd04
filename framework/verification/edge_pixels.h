// The pixels an edge crosses: a silhouette, a boundary between primitives, or the edge of a
// point light's hard shadow. A pixel's value there depends on where in the pixel it is
// sampled, so a render that samples the pixel centre and one whose samples spread, however
// little, disagree there by design. Blender Cycles 3.4 with a 0.01 px pixel filter still sends
// a few samples up to half a pixel from the centre (docs/verification.md#statistical-comparison),
// so the statistical comparison with its references leaves these pixels out.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/scene/scene.h"

#include <cstdint>
#include <vector>

namespace rtlab {

// One flag per pixel (y * width + x): 1 when the closest primitive, or the set of point lights
// that reach the surface point unshadowed, differs between the pixel's centre and any of its
// four corners and four edge midpoints.
std::vector<uint8_t> findEdgePixels(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                                    int width, int height);

}  // namespace rtlab
