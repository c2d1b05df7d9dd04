// Closed forms of radiometry in double, to judge estimators and renders by
// (docs/a6-radiometry.md#how-the-grader-checks-it). Like the oracle, this shares no code with any
// student file: where a6 asks for Van Oosterom and Strackee, the solid angle here comes from
// Girard's angle excess. Radiance 1 throughout: multiply by the emitter's radiance.
#pragma once

#include "framework/core/vec.h"

#include <span>
#include <vector>

namespace rtlab {

// The solid angle of triangle a, b, c seen from x: the angle excess of its spherical image
// (Girard), from the angles between the planes through x and its edges.
double triangleSolidAngleByExcess(const DVec3& x, const DVec3& a, const DVec3& b, const DVec3& c);

// The irradiance at x (unit normal n) from a flat polygon of radiance 1, entirely on the side
// n points to: Lambert's contour formula, E = 1/2 |sum_k theta_k (n . g_k)|, with theta_k the
// angle between the vectors from x to vertices k and k + 1 and g_k the unit normal of their
// plane. For a polygon that reaches below the horizon, clip it at x's tangent plane first.
double polygonIrradiance(const DVec3& x, const DVec3& n, std::span<const DVec3> polygon);

// The part of a convex polygon on the side of the plane through `point` that `normal` points
// to (Sutherland and Hodgman), vertices in the same order; empty when nothing is left.
std::vector<DVec3> clipPolygon(std::span<const DVec3> polygon, const DVec3& point, const DVec3& normal);

// The irradiance at x (unit normal n) from a sphere of radiance 1: pi sin^2(alpha) cos(theta)
// with sin(alpha) = radius / d and theta the angle between n and the direction to the centre.
// Only when the whole cap lies above the horizon (theta + alpha <= pi / 2); NaN otherwise.
double sphereIrradiance(const DVec3& x, const DVec3& n, const DVec3& centre, double radius);

}  // namespace rtlab
