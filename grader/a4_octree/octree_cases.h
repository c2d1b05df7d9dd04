// a4's hand-derived cases (docs/a4-octree.md): small scenes whose octrees were worked out node
// by node from the build rules, and the octree rows of the stress catalogue
// (docs/conventions.md#stress-catalogue, OCT-01 .. OCT-05) with their expected hits. The grader
// grades a student's functions on them; tests/test_octree.cpp holds the reference to them.
#pragma once

#include "framework/interface/octree.h"
#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct BuildCase {
    std::string id;
    Scene scene;
    OctreeOptions options;
    Octree expected;
};

// The worked example of the docs and its depth-0 variant, a cluster in one child of a node
// (split anyway), three copies of a triangle in the root's mid-plane (the memory rule), an
// empty scene, and a triangle with a NaN vertex among valid ones.
std::vector<BuildCase> buildCases();

struct OctreeStressRay {
    std::string id;
    Ray ray;
    uint32_t prim;  // kNoHit: a miss
    float t;        // when hit; exact (dyadic inputs) up to the triangle test's rounding
};

struct OctreeStressScene {
    std::string id;
    Scene scene;  // the root is [0,1]^3, forced by two anchor triangles (ids 0 and 1)
    std::vector<OctreeStressRay> rays;
};

// Built with maxPrims = 1 so that the walks cross many leaves and mid-planes.
std::vector<OctreeStressScene> octreeStressScenes();
OctreeOptions stressOptions();

}  // namespace rtlab::grader
