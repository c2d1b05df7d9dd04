// What a visit-order test finds (the BVH's in grader/a1_bvh/visit_order.h, the octree's in
// grader/a4_octree/octree_visit_order.h): how many rays were judged, how many visited their
// leaves out of order, and how many of those a correct traversal may still show.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace rtlab::grader {

struct VisitOrderVerdict {
    size_t graded = 0;               // rays judged (the others meet a box edge within rounding)
    size_t wrong = 0;
    std::vector<std::string> problems;  // the first few, one line each
    std::vector<size_t> wrongRays;      // their rays' indices, for the report's viewer links
};

// How many wrong rays a correct traversal may still show (primitive edges the double-precision
// oracle and a float test decide differently): 1 % of those graded, at least 2.
inline size_t allowedVisitOrderErrors(size_t graded) { return std::max<size_t>(2, graded / 100); }

}  // namespace rtlab::grader
