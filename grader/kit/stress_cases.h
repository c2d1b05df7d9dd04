// The unit cases of the numerical stress catalogue (docs/conventions.md#stress-catalogue), with
// their exact inputs and expected outputs, as the a0 tests use them.
// Ids follow the catalogue (BOX-01.3 is row 3 of BOX-01's truth table).
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct BoxCase {
    std::string id;
    Bounds3f box;
    Ray ray;  // tMin and tMax of the query
    bool hit;
    float enter;  // expected entry distance when hit
};

struct TriangleCase {
    std::string id;
    std::vector<std::array<Vec3, 3>> triangles;  // all tested with the same ray
    Ray ray;
    bool hit;       // at least one triangle hit (true) or none (false)
    float t;        // every hit at this distance
    float tolerance;  // relative
};

struct SphereCase {
    std::string id;
    Vec3 centre;
    float radius;
    Ray ray;
    bool hit;
    float t;
    float tolerance;  // relative
};

// BOX-01 (15 rows), BOX-02 (and with tMax on the box), BOX-03 (both boxes), BOX-06 plus two tMin rows.
std::vector<BoxCase> boxCases();
// TRI-01, TRI-02, TRI-05 (mirrored half), TRI-06..08, TRI-11..15, BIG-01.
std::vector<TriangleCase> triangleCases();
// Hand-derived sphere cases: outside, inside, behind, tMin/tMax, a distant small sphere
// (cancellation), large offsets, NaN and zero directions.
std::vector<SphereCase> sphereCases();

Ray makeRay(const Vec3& origin, const Vec3& direction, float tMin = 0.0f, float tMax = kInfinity);

}  // namespace rtlab::grader
