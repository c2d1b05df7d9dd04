// Camera rays that cannot reach the scene (docs/performance.md, "The renderer"). Most camera
// rays of a render often miss everything (69 % of the bunny's at 784x784), and each still costs
// the accelerator its set-up and a test of the root; these tests cost a few multiply-adds.
//
// The rays through one row of pixel centres leave the camera's position in one plane, the
// row's plane: their directions are forward + x * right / width + the row's term, affine in x.
// If the scene's bounds lie wholly on one side of the row's plane, no ray of the row reaches
// them (Row::missesAll). Otherwise the rays of a tile's row, between its first and last pixel
// edges, miss them if they lie wholly left of the plane through the first edge's ray normal to
// the row's plane, or wholly right of the last edge's (Row::misses). Seen from the camera, the
// first test cuts away the rows above and below the bounds, the second the tiles left and right
// of them. (The same side test on every pixel of the bunny's render skipped only 3 % more rays
// and cost more than it saved.)
//
// Conservative by a wide margin: the bounds are enlarged by 1e-5 of the distance from the
// camera to their far corner, against float rounding of the rays of about 1e-7 of that
// distance, and the planes are worked out in double. A camera inside the enlarged bounds, or
// bounds that are not finite, never skip a ray; bounds of nothing skip every ray.
#pragma once

#include "framework/core/bounds.h"
#include "framework/scene/camera.h"

#include <array>

namespace rtlab {

class BoundsCull {
public:
    enum class Mode { Test, Always, Never };

    // One row of pixel centres.
    class Row {
    public:
        // Whether no ray of the row reaches the bounds.
        bool missesAll() const { return all_; }
        // Whether no ray through film positions (x, the row's y) with x0 <= x <= x1 reaches
        // them. x0 and x1 may be pixel edges: the rays through the centres between lie between.
        bool misses(double x0, double x1) const;

    private:
        friend class BoundsCull;
        Mode mode_ = Mode::Never;
        bool all_ = false;
        // Corner c lies on the positive side of the plane through the ray at x when
        // offset[c] + x * slope[c] > 0.
        std::array<double, 8> offset_{}, slope_{};
    };

    BoundsCull(const CameraFilm& film, const Bounds3f& sceneBounds);

    // The row of pixel centres y + 0.5.
    Row row(int y) const;

private:
    CameraFilm film_;
    Mode mode_ = Mode::Never;
    std::array<DVec3, 8> corners_{};  // the enlarged bounds' corners, relative to the camera
};

}  // namespace rtlab
