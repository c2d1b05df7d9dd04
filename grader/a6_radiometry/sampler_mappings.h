// The mappings a6's samplers are pinned to (framework/interface/a6_radiometry.h,
// docs/a6-radiometry.md#samplers): the sample the contract gives for a pair u, computed in
// double from each mapping's definition, so the grader can check every sample against the u it
// was drawn from. A sampler that ignores u, or places its samples by quota to please a
// histogram, cannot pass this.
#pragma once

#include "framework/core/vec.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"

namespace rtlab::grader {

// The direction (or, for UniformTriangle, the point) the contract pins for u. The spherical
// triangle's is found from its definition, not from Arvo's closed form: C' is the point of the
// arc from A to C where the sub-triangle A, B, C' has u.x of the area (by bisection on the arc,
// areas by Girard's angle excess), and the direction the point of the arc from B to C' whose
// cosine to B is 1 - u.y (1 - C'.B).
DVec3 pinnedSample(const worker::SamplerCall& call, Vec2 u);

// How far a returned sample may lie from the pinned one: 2e-3 for unit directions (a float
// implementation of Arvo's formulas is off by up to 1.1e-3 on the grader's triangles, every
// other sampler by less than 1e-5 but near the poles, where the square root of 1 - z^2 in float
// moves a direction by up to 5e-4); for points of a triangle 2e-3 of its longest edge plus the
// float rounding of its coordinates. A sampler with another mapping is off by a sizeable part
// of its domain.
double pinnedTolerance(const worker::SamplerCall& call);

}  // namespace rtlab::grader
