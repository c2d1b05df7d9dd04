// A perspective pinhole camera that maps pixels to rays exactly as POV-Ray 3.7 does: one ray
// through each pixel centre, the image spanning the full right and up vectors
// (docs/conventions.md, "Camera").
#pragma once

#include "framework/core/ray.h"

#include <string>

namespace rtlab {

// The camera's film for one image size, set up once: every ray through it costs a few
// multiply-adds and one normalisation, not a tangent and three normalisations.
struct CameraFilm {
    Vec3 origin{0.0f};   // every ray's origin: the camera's position, rounded to float once
    DVec3 forward{0.0};  // D: from the eye to the film's centre
    DVec3 right{0.0};    // R: the film's full width
    DVec3 up{0.0};       // U: the film's full height
    double width = 1.0, height = 1.0;

    // The two terms of the direction through film position (x, y), in pixel units from the
    // top-left corner: the column's point on the film's horizontal centre line, and the row's
    // offset from it. A renderer computes each once per column and once per row.
    DVec3 column(double x) const { return forward + (x / width - 0.5) * right; }
    DVec3 row(double y) const { return (0.5 - y / height) * up; }

    Ray through(const DVec3& column, const DVec3& row) const {
        Ray ray;
        ray.origin = origin;
        ray.direction = Vec3(glm::normalize(column + row));
        return ray;
    }
    Ray through(double x, double y) const { return through(column(x), row(y)); }

    // through(columns[i], row) for i < count, made together: the same arithmetic, written one
    // component at a time so that the compiler does the square roots and divisions of several
    // rays in one instruction. A renderer makes a tile's row of centre rays this way.
    void throughRow(const DVec3* columns, int count, const DVec3& row, Ray* rays) const;
};

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
    // The film of a width x height image, for rendering many rays with the same construction.
    CameraFilm film(int width, int height) const;
};

}  // namespace rtlab
