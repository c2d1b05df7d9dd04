// Camera::generateRay against POV-Ray's camera, rebuilt here in double exactly as
// docs/verification.md#1-the-exporter-rtlab-export-pov describes Parser::Parse_Camera and
// TracePixel::CreateCameraRay, for the glTF recipe
//   location P  right -x*W/H  up y  angle degrees(2 atan(W/H tan(yfov/2)))  sky S  look_at P+F.
#include "framework/scene/camera.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace rtlab;

namespace {

struct PovCamera {
    DVec3 location, direction, right, up;
};

PovCamera povCamera(const DVec3& location, const DVec3& lookAt, const DVec3& sky, double yfov, int width,
                    int height) {
    double aspect = static_cast<double>(width) / height;
    DVec3 right(-aspect, 0.0, 0.0);  // right-handed data: negative right
    DVec3 up(0.0, 1.0, 0.0);
    DVec3 direction(0.0, 0.0, 1.0);
    // angle (horizontal field of view): |D| = |R| / tan(A/2) / 2.
    double angle = 2.0 * std::atan(aspect * std::tan(yfov / 2.0));
    direction = glm::normalize(direction) * (glm::length(right) / std::tan(angle / 2.0) / 2.0);
    // look_at keeps the lengths and the handedness of the vectors before it.
    double dl = glm::length(direction), ul = glm::length(up), rl = glm::length(right);
    double handedness = glm::dot(glm::cross(up, direction), right);
    direction = glm::normalize(lookAt - location);
    right = glm::normalize(glm::cross(sky, direction));
    up = glm::cross(direction, right);
    return {location, direction * dl, right * (handedness > 0 ? rl : -rl), up * ul};
}

DVec3 povRayDirection(const PovCamera& camera, int i, int j, int width, int height) {
    double x = i + 0.5, y = j - 0.5;  // CreateCameraRay's adjustments
    double x0 = x / width - 0.5;
    double y0 = ((height - 1) - y) / height - 0.5;
    return glm::normalize(camera.direction + x0 * camera.right + y0 * camera.up);
}

void checkAgainstPovRay(const Camera& camera, int width, int height) {
    PovCamera pov = povCamera(camera.position, camera.position + camera.forward, camera.up, camera.yfov, width,
                              height);
    double worst = 0.0;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            Ray ray = camera.generateRay(i, j, width, height);
            DVec3 expected = povRayDirection(pov, i, j, width, height);
            worst = std::max(worst, glm::length(DVec3(ray.direction) - expected));
            REQUIRE(ray.origin == Vec3(camera.position));
        }
    }
    // A unit direction rounded once to float is within half an ulp of 1 per component.
    CHECK(worst <= 1e-7);
}

}  // namespace

TEST_CASE("camera: tilted camera, tilted sky, non-square image match POV-Ray's rays") {
    Camera camera;
    camera.position = {1.9, 1.6, 1.7};
    camera.forward = DVec3(0.5, 0.5, 0.5) - camera.position;  // not unit length
    camera.up = {0.3, 1.0, -0.2};                              // not orthogonal to forward
    camera.yfov = 0.43;
    checkAgainstPovRay(camera, 80, 50);
    checkAgainstPovRay(camera, 33, 71);  // portrait, odd sizes
}

TEST_CASE("camera: default glTF orientation, pixel (0,0) is the top-left corner") {
    Camera camera;  // at the origin, looking down -Z, +Y up
    camera.yfov = 1.0;
    checkAgainstPovRay(camera, 64, 48);
    Ray topLeft = camera.generateRay(0, 0, 64, 48);
    CHECK(topLeft.direction.x < 0.0f);  // right-handed: +X is to the right
    CHECK(topLeft.direction.y > 0.0f);
    CHECK(topLeft.direction.z < 0.0f);
    // The centre of a 2x2 image lies between pixel centres: rays go through pixel centres,
    // so pixel (1,1) is half a pixel right of and below the axis.
    Ray centre = camera.generateRay(1, 1, 2, 2);
    double halfHeight = std::tan(0.5);
    CHECK(centre.direction.x / -centre.direction.z == doctest::Approx(0.5 * halfHeight).epsilon(1e-6));
    CHECK(centre.direction.y / -centre.direction.z == doctest::Approx(-0.5 * halfHeight).epsilon(1e-6));
}

TEST_CASE("camera: the film set up once gives generateRay's rays bit for bit, by columns and rows") {
    Camera camera;
    camera.position = {0.4, -1.3, 2.2};
    camera.forward = {-0.2, 0.3, -1.0};
    camera.up = {0.1, 1.0, 0.05};
    camera.yfov = 0.7;
    const int width = 37, height = 23;
    CameraFilm film = camera.film(width, height);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            // The renderer's path: one column term per column, one row term per row.
            Ray byTerms = film.through(film.column(i + 0.5), film.row(j + 0.5));
            Ray reference = camera.generateRay(i, j, width, height);
            REQUIRE(std::memcmp(&byTerms.direction, &reference.direction, sizeof(Vec3)) == 0);
            REQUIRE(byTerms.origin == reference.origin);
            // Between pixel centres (stratified samples), through the same film.
            Ray inside = film.through(i + 0.125, j + 0.875);
            Ray insideReference = camera.generateRayThrough(i + 0.125, j + 0.875, width, height);
            REQUIRE(std::memcmp(&inside.direction, &insideReference.direction, sizeof(Vec3)) == 0);
        }
        // A whole row at once, as the renderer makes a tile's rays: 37 columns are two full
        // batches of 16 and a part-filled one.
        std::vector<DVec3> columns;
        for (int i = 0; i < width; ++i) columns.push_back(film.column(i + 0.5));
        std::vector<Ray> row(width);
        film.throughRow(columns.data(), width, film.row(j + 0.5), row.data());
        for (int i = 0; i < width; ++i) {
            Ray reference = camera.generateRay(i, j, width, height);
            REQUIRE(std::memcmp(&row[i].direction, &reference.direction, sizeof(Vec3)) == 0);
            REQUIRE(row[i].origin == reference.origin);
            REQUIRE(row[i].tMin == reference.tMin);
            REQUIRE(row[i].tMax == reference.tMax);
        }
    }
}
