#include "grader/kit/stress_scenes.h"

#include "grader/kit/test_scenes.h"

#include <cmath>
#include <limits>

namespace rtlab::grader {

std::vector<StressScene> stressScenes() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<StressScene> scenes;
    auto ray = [](Vec3 o, Vec3 d, float tMax = kInfinity) {
        Ray r;
        r.origin = o;
        r.direction = d;
        r.tMax = tMax;
        return r;
    };
    {
        SceneBuilder b;
        for (int a = 1; a <= 64; ++a) b.addTriangle({-float(a), -1, -1}, {float(a), -1, 1}, {0, 2, 0});
        scenes.push_back({"BVH-01 identical centroids", b.take(), {{ray({0.5f, 0, 10}, {0, 0, -1}), false, true, {0}, 9.5f}}});
    }
    {
        SceneBuilder b;
        for (int k = 0; k < 64; ++k) b.addTriangle({float(k), -1, -100}, {float(k), 1, -100}, {float(k), 0, 200});
        scenes.push_back({"BVH-02 zero centroid extent on the longest axis", b.take(), {{ray({-1, 0, 0}, {1, 0, 0}), false, true, {0}, 1}}});
    }
    {
        SceneBuilder b;
        std::vector<StressRay> rays;
        const float centres[] = {0.0f, 0.5f, 1.0f, 3.0f, 3.1f};
        for (uint32_t i = 0; i < 5; ++i) {
            float cx = centres[i];
            b.addTriangle({cx - 0.1f, 5.0f * i, 0}, {cx + 0.1f, 5.0f * i, 0}, {cx, 5.0f * i + 0.1f, 0.1f});
            rays.push_back({ray({cx, 5.0f * i + 0.05f, 1}, {0, 0, -1}), false, true, {i}, 0.95f});
        }
        scenes.push_back({"BVH-03 bucket index clamp", b.take(), rays});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        scenes.push_back({"BVH-07 one primitive", b.take(), {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, {0}, 1}}});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
        scenes.push_back({"BVH-07 two identical primitives", b.take(), {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, {0, 1}, 1}}});
    }
    {
        SceneBuilder b;
        for (int i = 0; i < 10; ++i) b.addTriangle({float(i), 0, 0}, {i + 0.5f, 0, 0}, {float(i + 1), 0, 0});
        std::vector<StressRay> rays = {{ray({2.25f, 0, 5}, {0, 0, -1}), false, false, {}, 0},
                                       {ray({-1, 0, 0}, {1, 0, 0}), false, false, {}, 0},
                                       {ray({2.25f, 0, 5}, {0, 0, -1}, 10), true, false, {}, 0}};
        scenes.push_back({"BVH-08 degenerate primitives only", b.take(), rays});
        SceneBuilder mixed;
        for (int i = 0; i < 10; ++i) mixed.addTriangle({float(i), 0, 0}, {i + 0.5f, 0, 0}, {float(i + 1), 0, 0});
        mixed.addTriangle({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
        scenes.push_back({"BVH-08 degenerate and valid", mixed.take(), {{ray({1, 1, 5}, {0, 0, -1}), false, true, {10}, 6}}});
    }
    {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
        b.addTriangle({1, 1, 1}, {1, 1, 1}, {1, 1, 1});
        b.addTriangle({0, 0, 0}, {0, 0, 0}, {1, 0, 0});
        b.addTriangle({0, 0, -1}, {4, 0, -1}, {0, 4, -1});
        scenes.push_back({"TRI-12 degenerate triangles", b.take(), {{ray({1, 1, 5}, {0, 0, -1}), false, true, {3}, 6}}});
    }
    {
        // Midpoint splits on centroids x = 2^-k peel two primitives off per level while the
        // smallest centroid is below the midpoint's rounding, then one: 150 of them (the last
        // ones subnormal) reach the depth cap. A ray along +x meets both children at every
        // level and keeps one pending per level: a traversal stack smaller than kMaxBvhDepth
        // overflows. Float rounds 1 + 2^-k to 1 for k >= 24, so those primitives tie at t = 1.
        SceneBuilder b;
        std::vector<uint32_t> tied;
        for (int k = 0; k < 150; ++k) {
            float x = std::ldexp(1.0f, -k);
            b.addTriangle({x, -1, -1}, {x, 1, -1}, {x, 0, 1});
            if (k >= 20) tied.push_back(uint32_t(k));
        }
        scenes.push_back({"BVH-10 a tree as deep as the cap", b.take(), {{ray({-1, 0, 0}, {1, 0, 0}), false, true, tied, 1}}});
    }
    {
        // More identical primitives than a leaf's 16-bit primCount holds: splitNode makes this
        // a leaf (equal centroids), and buildBvh must split it anyway.
        SceneBuilder b;
        std::vector<uint32_t> all;
        for (uint32_t i = 0; i < 70000; ++i) {
            b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
            all.push_back(i);
        }
        scenes.push_back({"BVH-11 70000 identical primitives", b.take(), {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, all, 1}}});
    }
    {
        // Triangles of side 2^62 spread over 31 * 2^62: the root's surface area, 62 * 2^124,
        // overflows float (FLT_MAX < 2^128) while every edge function and a leaf's area do not,
        // so only SAH costs computed in float go wrong (all infinite: no split found).
        SceneBuilder b;
        const float s = 0x1p62f;
        for (int k = 0; k < 16; ++k) b.addTriangle({k * 2 * s, 0, 0}, {k * 2 * s + s, 0, 0}, {k * 2 * s, s, 0});
        scenes.push_back({"BVH-12 coordinates near 2^62", b.take(), {{ray({0x1p60f, 0x1p60f, 1}, {0, 0, -1}), false, true, {0}, 1}}});
    }
    for (float bad : {nan, kInfinity}) {
        SceneBuilder b;
        b.addTriangle({0, 0, 0}, {1, 0, 0}, {bad, 1, 0});
        b.addTriangle({0, 0, -1}, {1, 0, -1}, {0, 1, -1});
        std::vector<StressRay> rays = {{ray({0.2f, 0.2f, 1}, {0, 0, -1}), false, true, {1}, 2},
                                       {ray({0.2f, 0.2f, 1}, {0, 0, -1}, 1.5f), true, false, {}, 0}};
        scenes.push_back({std::string("TRI-13 ") + (std::isnan(bad) ? "NaN" : "infinite") + " vertex", b.take(), rays});
    }
    {
        // 100 copies of one triangle, with BVH-01's set 10 below them: no plane lies strictly
        // inside the copies' box, so a KD-tree must stop splitting them (a builder that splits
        // until a child is smaller never ends).
        SceneBuilder b;
        std::vector<uint32_t> copies;
        for (uint32_t i = 0; i < 100; ++i) {
            b.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
            copies.push_back(i);
        }
        for (int a = 1; a <= 64; ++a) b.addTriangle({-float(a), -1, -11}, {float(a), -1, -9}, {0, 2, -10});
        scenes.push_back({"KD-05 100 identical triangles", b.take(),
                          {{ray({0.25f, 0.25f, 1}, {0, 0, -1}), false, true, copies, 1}, {ray({0.25f, 0.25f, 1}, {0, 0, -1}, 0.5f), true, false, {}, 0}}});
    }
    {
        // Five triangles side by side in z = 0, their boxes abutting at x = 1 .. 4 (pbrt-v3#244):
        // an End and a Start at every shared x. The ray at x = 2 meets triangle 2's edge only.
        SceneBuilder b;
        for (int k = 0; k < 5; ++k) b.addTriangle({float(k), 0, 0}, {float(k + 1), 0, 0}, {float(k), 1, 0});
        scenes.push_back({"KD-06 five abutting coplanar triangles", b.take(),
                          {{ray({2, 0.25f, 1}, {0, 0, -1}), false, true, {2}, 1},
                           {ray({1.5f, 0.25f, 1}, {0, 0, -1}), false, true, {1}, 1},
                           {ray({4.75f, 0.75f, 1}, {0, 0, -1}), false, false, {}, 0}}});
    }
    // Every box flat in z: zero-width grid cells and KD-tree nodes (square (4, 2)'s lower-right
    // triangle is primitive 72); a ray in the plane hits nothing.
    scenes.push_back({"GRID-06 a flat scene", flatScene().scene,
                      {{ray({1.15f, 0.55f, 1}, {0, 0, -1}), false, true, {72}, 1},
                       {ray({-1, 0.6f, 0}, {1, 0, 0}), false, false, {}, 0},
                       {ray({1.15f, 0.55f, 1}, {0, 0, -1}, 0.5f), true, false, {}, 0}}});
    return scenes;
}

}  // namespace rtlab::grader
