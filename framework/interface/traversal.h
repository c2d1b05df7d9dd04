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
// When the stats point at a TraversalTrace (traversal_trace.h), every operation is also
// recorded there in order, for the viewer.
#pragma once

#include "framework/core/hit.h"
#include "framework/core/ray.h"
#include "framework/interface/a0_intersect.h"
#include "framework/interface/mailbox.h"
#include "framework/interface/traversal_stats.h"
#include "framework/interface/traversal_trace.h"

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
        : primitives_(primitives), ray_(ray), inverse_(ray), stats_(stats), trace_(stats.trace) {
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
        bool hit = intersectBox(box, inverse_, ray_.tMin, tMax, tEnter);
        if (trace_) trace_->addBox(box, hit, tEnter ? *tEnter : 0.0f, tMax);
        return hit;
    }

    void countCellStep() {
        ++stats_.cellSteps;
        if (trace_) trace_->add(TraceOp{TraceOpKind::CellStep});
    }
    // A leaf of a spatial tree the walk enters, by its node index: counted as a cell step, and
    // listed for the grader's visit-order test when a list is set.
    void enterLeaf(uint32_t node) {
        ++stats_.cellSteps;
        if (entered_) entered_->push_back(node);
        if (trace_) trace_->add(TraceOp{TraceOpKind::LeafEntry, 0, 0, node});
    }
    void countPlaneStep() {
        ++stats_.planeSteps;
        if (trace_) trace_->add(TraceOp{TraceOpKind::PlaneStep});
    }

    // One primitive test for a closest-hit query: updates hit when prim is hit in
    // (tMin, hit.t].
    bool intersect(uint32_t prim, Hit& hit) {
        ++stats_.primitiveTests;
        if (tested_) tested_->push_back(prim);
        float closest = hit.t;
        bool found = intersectPrimitive(primitives_, prim, ray_, hit);
        if (trace_) trace_->add(TraceOp{TraceOpKind::PrimitiveTest, uint8_t(found), 0, prim, found ? hit.t : 0.0f, closest});
        return found;
    }
    // One primitive test for an any-hit query: does prim block the segment (tMin, tMax]?
    bool occludes(uint32_t prim) {
        ++stats_.primitiveTests;
        Hit hit;
        hit.t = ray_.tMax;
        bool found = intersectPrimitive(primitives_, prim, ray_, hit);
        if (trace_) trace_->add(TraceOp{TraceOpKind::PrimitiveTest, uint8_t(found), 0, prim, found ? hit.t : 0.0f, ray_.tMax});
        return found;
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
        if (trace_) trace_->add(TraceOp{TraceOpKind::MailboxRepeat, 0, 0, prim});
        return false;
    }

    const PrimitiveSet& primitives_;
    const Ray& ray_;
    RayInverse inverse_;
    TraversalStats& stats_;
    Mailbox mailbox_;
    std::vector<uint32_t>* tested_ = nullptr;
    std::vector<uint32_t>* entered_ = nullptr;
    TraversalTrace* trace_;
};

}  // namespace rtlab
