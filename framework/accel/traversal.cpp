// The primitive tests of the Traversal context (framework/interface/traversal.h), here because
// they need the primitive set, which the student contract only names.
#include "framework/interface/traversal.h"

#include "framework/accel/primitive_set.h"

namespace rtlab {

bool Traversal::intersect(uint32_t prim, Hit& hit) {
    ++stats_.primitiveTests;
    if (tested_) tested_->push_back(prim);
    return primitives_.intersect(prim, ray_, hit);
}

bool Traversal::occludes(uint32_t prim) {
    ++stats_.primitiveTests;
    Hit hit;
    hit.t = ray_.tMax;
    return primitives_.intersect(prim, ray_, hit);
}

}  // namespace rtlab
