// The per-query context every traversal works through, whoever wrote it. It owns the ray, its
// precomputed slab data and the work counters, and offers one counted operation per kind of
// work a structure does:
//   hitsBox       a box test (a BVH or octree node, the grid's bounds)
//   countCellStep a cell the grid's 3D-DDA enters
//   enterLeaf     a leaf a tree walk enters (the octree's), counted with the cell steps
//   countPlaneStep a split plane a KD-tree traversal classifies the ray against
//   intersect / occludes            a primitive test
//   intersectOnce / occludesOnce    the same behind a mailbox: a primitive referenced from
//                                   several cells is tested once per ray, repeats are counted
// The counters are the framework's: feedback for students and the bench, never the grader's
// evidence (that is the CPU time it measures itself, docs/grading.md#isolation-and-trust).
#pragma once

#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/a0_intersect.h"
#include "framework/interface/mailbox.h"
#include "framework/interface/traversal_stats.h"

#include <array>
#include <vector>

namespace rtlab {

class PrimitiveSet;  // framework/accel/primitive_set.h

// One ray-primitive test against the primitive set's data (framework/accel/primitive_set.cpp):
// updates hit when prim is hit in (ray.tMin, hit.t].
bool intersectPrimitive(const PrimitiveSet& primitives, uint32_t prim, const Ray& ray, Hit& hit);

class Traversal {
public:
    Traversal(const PrimitiveSet& primitives, const Ray& ray, TraversalStats& stats)
        : primitives_(primitives), ray_(ray), inverse_(ray), stats_(stats) {
        ++stats_.rays;
    }

    const Ray& ray() const { return ray_; }
    const RayInverse& inverse() const { return inverse_; }
    // Direction sign per axis (1 = negative, -0.0 included): decides the near child.
    const std::array<int, 3>& dirIsNegative() const { return inverse_.dirIsNegative; }

    // One box test: does the ray's segment (tMin, tMax] touch the box? *tEnter receives the
    // entry distance, which ordered traversals use to skip far children.
    bool hitsBox(const Bounds3f& box, float tMax, float* tEnter) {
        ++stats_.nodeVisits;
        return intersectBox(box, inverse_, ray_.tMin, tMax, tEnter);
    }

    void countCellStep() { ++stats_.cellSteps; }
    // A leaf of a spatial tree the walk enters, by its node index: counted as a cell step, and
    // listed for the grader's visit-order test when a list is set.
    void enterLeaf(uint32_t node) {
        ++stats_.cellSteps;
        if (entered_) entered_->push_back(node);
    }
    void countPlaneStep() { ++stats_.planeSteps; }

    // One primitive test for a closest-hit query: updates hit when prim is hit in
    // (tMin, hit.t].
    bool intersect(uint32_t prim, Hit& hit) {
        ++stats_.primitiveTests;
        if (tested_) tested_->push_back(prim);
        return intersectPrimitive(primitives_, prim, ray_, hit);
    }
    // One primitive test for an any-hit query: does prim block the segment (tMin, tMax]?
    bool occludes(uint32_t prim) {
        ++stats_.primitiveTests;
        Hit hit;
        hit.t = ray_.tMax;
        return intersectPrimitive(primitives_, prim, ray_, hit);
    }

    // Lists every primitive a closest-hit query tests, in order, into *list (null: no list): the
    // grader's visit-order test reads it. The framework sets it, never student code.
    void listTestsIn(std::vector<uint32_t>* list) { tested_ = list; }
    // Lists every leaf enterLeaf reports, in order, into *list (null: no list); the same.
    void listLeavesIn(std::vector<uint32_t>* list) { entered_ = list; }

    // The mailboxed forms: a primitive this ray has tested already is not tested again (its
    // hit, if any, is in hit already) and returns false.
    bool intersectOnce(uint32_t prim, Hit& hit) { return firstVisit(prim) && intersect(prim, hit); }
    bool occludesOnce(uint32_t prim) { return firstVisit(prim) && occludes(prim); }

private:
    bool firstVisit(uint32_t prim) {
        if (mailbox_.firstVisit(prim)) return true;
        ++stats_.mailboxRepeats;
        return false;
    }

    const PrimitiveSet& primitives_;
    const Ray& ray_;
    RayInverse inverse_;
    TraversalStats& stats_;
    Mailbox mailbox_;
    std::vector<uint32_t>* tested_ = nullptr;
    std::vector<uint32_t>* entered_ = nullptr;
};

}  // namespace rtlab
