// Camera rays that cannot reach the scene (docs/performance.md, "The renderer"). Most camera
// rays of a render often miss everything (69 % of the bunny's at 784x784), and each still costs
// the accelerator its set-up and a test of the root; these tests cost a few multiply-adds per
// tile row.
//
// The scene is held as a few boxes (sceneBoxes: its primitives' bounds in each octant of its
// bounding box, a tighter hull than the one box). The rays through one row of pixel centres
// leave the camera's position in one plane, the row's plane: their directions are forward +
// x * right / width + the row's term, affine in x. A box is out of reach of the rays of a
// tile's row, between its first and last pixel edges, if it lies wholly on one side of the
// row's plane, or wholly left of the plane through the first edge's ray normal to the row's
// plane, or wholly right of the last edge's. Seen from the camera, the first test cuts away the
// rows above and below the box, the others the tiles left and right of it. A row skips its rays
// when every box is out of reach. (The side test on every pixel instead of every tile skipped
// 3 % more of the bunny's rays with one box and cost more than it saved.)
//
// Conservative by a wide margin: each box is enlarged by 1e-5 of the distance from the camera
// to its far corner, against float rounding of the rays of about 1e-7 of that distance, and the
// planes are worked out in double. A camera inside an enlarged box, or a box that is not
// finite, never lets a row be skipped; no boxes skip every row.
#pragma once

#include "framework/core/bounds.h"
#include "framework/scene/camera.h"
#include "framework/scene/scene.h"

#include <array>
#include <span>
#include <vector>

namespace rtlab {

// The bounds of the scene's primitives in each octant of its bounding box, by their boxes'
// centres; the empty ones left out.
std::vector<Bounds3f> sceneBoxes(const Scene& scene);

class BoundsCull {
public:
    // One row of pixel centres.
    class Row {
    public:
        // Whether no ray through film positions (x, the row's y) with x0 <= x <= x1 reaches any
        // box. x0 and x1 may be pixel edges: the rays through the centres between lie between.
        bool misses(double x0, double x1) const;

    private:
        friend class BoundsCull;
        // One box: corner c lies on the positive side of the plane through the ray at x when
        // offset[c] + x * slope[c] > 0.
        struct Side {
            bool never = false;     // the camera inside the box, or the box not finite
            bool outOfRow = false;  // wholly on one side of the row's plane
            std::array<double, 8> offset{}, slope{};
        };
        std::vector<Side> boxes_;
    };

    BoundsCull(const CameraFilm& film, std::span<const Bounds3f> boxes);

    // The row of pixel centres y + 0.5.
    Row row(int y) const;

private:
    struct Box {
        bool never = false;
        std::array<DVec3, 8> corners{};  // enlarged, relative to the camera
    };

    CameraFilm film_;
    std::vector<Box> boxes_;
};

}  // namespace rtlab
