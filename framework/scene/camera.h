// A perspective pinhole camera that maps pixels to rays exactly as POV-Ray 3.7 does: one ray
// through each pixel centre, the image spanning the full right and up vectors
// (docs/conventions.md, "Camera").
#pragma once

#include "framework/core/ray.h"

#include <string>

namespace rtlab {

struct Camera {
    std::string name;
    DVec3 position{0.0, 0.0, 0.0};
    DVec3 forward{0.0, 0.0, -1.0};  // the glTF camera looks down its local -Z
    DVec3 up{0.0, 1.0, 0.0};        // local +Y
    double yfov = 0.8;              // vertical field of view [rad]
    double aspectRatio = 0.0;       // from glTF; 0 = use the image's

    // Ray through the centre of pixel (column i, row j from the top) of a width x height image.
    Ray generateRay(int i, int j, int width, int height) const;
    // Ray through any film position (x, y) in pixel units from the top-left corner: the pixel
    // centre of (i, j) is (i + 0.5, j + 0.5). For antialiasing with samples inside a pixel.
    Ray generateRayThrough(double x, double y, int width, int height) const;
};

}  // namespace rtlab
