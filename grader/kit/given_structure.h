// The traversal graded on a structure the grader built
// (docs/grading.md#the-traversal-follows-its-structure). A traversal that walks a private
// structure (a BVH made during the build, say) answers for the scene whatever its cells or
// leaves hold, so checking the student's structure and the traversal's hits apart proves
// nothing. Here the grader builds a structure of its own, leaves some primitives out of some of
// its leaves, hands it to the student's traversal, and asks that every answer follow that
// structure, not the scene:
//  * a hit must be on a primitive some leaf lists: walking the structure cannot find one it
//    does not hold (any leaf, since a traversal that also opens leaves the ray misses only
//    wastes time);
//  * no hit may lie beyond a robust hit of a primitive listed in a leaf that contains that hit
//    point: walking front to back, that leaf is reached (or a nearer hit ends the walk) before
//    the traversal may stop.
// Both rules hold for every correct variant the contracts allow (mailbox or not, hits kept from
// earlier leaves or not, ties either way), and rays within rounding of a leaf's box or of a
// primitive's edge accept either answer. Which primitives are left out of which leaves comes
// from a key drawn afresh for every grading run, so no answer can be computed in advance.
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"
#include "framework/scene/scene.h"
#include "grader/kit/hit_judge.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::grader {

// The leaves of a structure as its traversal sees them: the region each one covers (a grid
// cell, an octree or KD-tree leaf's box, a BVH leaf's bounds) and the primitives it lists.
struct LeafList {
    std::vector<Bounds3f> boxes;
    std::vector<std::vector<uint32_t>> prims;
};

// Leaves primitives out of leaves, drawn from key: about one primitive in ten from every leaf,
// and about one in three from all of its leaves but one. With keepLeavesFilled (a BVH, whose
// empty leaf would read as an interior node) no leaf loses its last primitive.
void leaveOut(LeafList& leaves, uint32_t primCount, uint64_t key, bool keepLeavesFilled);

// The grader's structure for a given-structure query phase: its bytes for the worker task (the
// structure, before `u8 QueryKind, [Ray]`) and its leaves for the judge.
struct GivenStructure {
    std::vector<uint8_t> encoded;
    LeafList leaves;
};

class GivenStructureJudge {
public:
    GivenStructureJudge(LeafList leaves, const Scene& scene);

    // Empty when the answer follows the structure (see above), else what was wrong. `judge`
    // holds the scene's candidates for these rays; the answer must also be a real hit.
    std::string judgeClosest(HitJudge& judge, size_t index, const Ray& ray, const HitAnswer& answer) const;
    std::string judgeOccluded(HitJudge& judge, size_t index, const Ray& ray, bool occluded) const;

    // The words every problem that shows a hit on a primitive the structure does not hold
    // starts with: the mark of a traversal that does not walk what it was given.
    static constexpr const char* kNotInStructure = "not held by any leaf of the structure";

private:
    // Some leaf lists prim. Not "some leaf along the ray": a traversal that also visits leaves
    // the ray misses (beyond the tree's far faces, behind the origin) only loses time on the
    // real structure, and must lose no hits here.
    bool heldByStructure(uint32_t prim) const;
    // Some leaf of prim's box, shrunk by the slack, contains the point at t.
    bool surelyListed(uint32_t prim, const Ray& ray, double t) const;

    LeafList leaves_;
    std::vector<std::vector<uint32_t>> leavesOfPrim_;
    double slack_;  // how far float rounding may move a leaf's face: 1e-5 of the scene's scale
};

}  // namespace rtlab::grader
