// Small scenes built in code for the Blender tests (tests/test_blender_*.cpp), in glTF's
// convention (+Y up), with a camera each.
#pragma once

#include "framework/core/vec.h"
#include "framework/scene/scene.h"

#include <cmath>
#include <numbers>

namespace rtlab::test {

// Two triangles corner, corner + u, corner + u + v, corner + v: the front face is the side
// u x v points to.
inline void addQuad(Scene& scene, Vec3 corner, Vec3 u, Vec3 v, uint32_t material) {
    auto base = static_cast<uint32_t>(scene.triangles.positions.size());
    scene.triangles.positions.insert(scene.triangles.positions.end(), {corner, corner + u, corner + u + v, corner + v});
    scene.triangles.indices.push_back({base, base + 1, base + 2});
    scene.triangles.indices.push_back({base, base + 2, base + 3});
    scene.triangles.material.insert(scene.triangles.material.end(), {material, material});
    scene.triangles.smooth.insert(scene.triangles.smooth.end(), {0, 0});
}

inline Camera lookingAt(DVec3 position, DVec3 target, DVec3 up, double yfovDegrees) {
    Camera camera;
    camera.name = "camera";
    camera.position = position;
    camera.forward = glm::normalize(target - position);
    camera.up = up;
    camera.yfov = yfovDegrees * std::numbers::pi / 180.0;
    return camera;
}

// A floor (y = 0, 8 m wide, albedo (0.8, 0.6, 0.3)) under a square light of radiance L facing
// down at height 1 (front face down), a 0.3 m grey card halfway casting a soft shadow, seen
// from the side and above.
inline Scene emitterScene(Vec3 radiance) {
    Scene scene;
    scene.sourcePath = "emitter-scene (test)";
    scene.materials = {Material{"floor", Vec3(0.8f, 0.6f, 0.3f), Vec3(0.0f)},
                       Material{"card", Vec3(0.5f), Vec3(0.0f)},
                       Material{"light", Vec3(0.0f), radiance}};
    addQuad(scene, {-4, 0, 4}, {8, 0, 0}, {0, 0, -8}, 0);                 // faces up
    addQuad(scene, {-0.1f, 0.5f, -0.2f}, {0.3f, 0, 0}, {0, 0, 0.3f}, 1);   // faces down
    addQuad(scene, {-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, 2);            // faces down
    scene.cameras = {lookingAt({1.6, 1.4, 2.2}, {0.1, 0.0, 0.0}, {0, 1, 0}, 45.0)};
    return scene;
}

}  // namespace rtlab::test
