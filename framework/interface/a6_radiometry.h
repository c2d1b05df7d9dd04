// Assignment a6 (docs/a6-radiometry.md): radiometric units, solid angles, samplers with their
// densities, and Monte Carlo estimators of direct light.
// Implemented in assignments/a6_radiometry/ (yours) and solutions/a6_radiometry/ (reference).
//
// Shared contract:
//  * u is a pair of independent uniform numbers in [0, 1); every sampler maps it as its comment
//    says (the grader checks that mapping on given u and on samples whose u it knows, besides
//    the distribution and the pdf; the renderer's stratification needs a continuous map);
//  * an estimator returns ONE sample of the radiance the shading point reflects towards its
//    viewer, L = integral of (albedo / pi) L_e cos(theta_x) over the light's solid angle, where
//    theta_x is measured from ShadingPoint::normal; light from below the horizon
//    (cos(theta_x) <= 0) counts nothing, and neither does a sample whose density is 0;
//  * shadow rays go through SceneRays::visible, light found by direction through
//    SceneRays::incomingEmission: never test geometry yourself.
#pragma once

#include "framework/core/vec.h"
#include "framework/interface/radiometry.h"

#include <functional>

namespace rtlab {

// --- Units (assignments/a6_radiometry/units.cpp) -----------------------------------------------

double energyFromPower(double watts, double seconds);       // Q = Phi t            [J]
double powerFromEnergy(double joules, double seconds);      // Phi = Q / t          [W]
double intensityFromPower(double watts);                    // isotropic: I = Phi / 4 pi   [W/sr]
double powerFromIntensity(double wattsPerSteradian);        // isotropic: Phi = 4 pi I     [W]
// E = I cos(theta) / d^2 on a surface at distance d, tilted by theta from the light  [W/m^2]
double irradianceFromIntensity(double wattsPerSteradian, double distance, double cosTheta);
// A Lambertian emitter of area A, one-sided: Phi = pi L A, so L = Phi / (pi A)   [W/(m^2 sr)]
double radianceFromPower(double watts, double area);
double powerFromRadiance(double radiance, double area);
double irradianceFromRadiance(double radiance);  // uniform L over the whole hemisphere: E = pi L
// 683 lm per W at 555 nm, the peak of the eye's sensitivity (the definition of the candela):
double lumensFromWatts(double watts);
double wattsFromLumens(double lumens);

// --- Solid angles (assignments/a6_radiometry/solid_angle.cpp) ----------------------------------
// In steradians, in double, accurate to 1e-9 relative also for tiny angles: write 1 - cos a as
// 2 sin^2(a/2), which holds for every a in [0, pi] (the plain difference loses every digit for a
// star). sin^2 a / (1 + cos a) holds only away from pi: fine for a sphere (a <= pi/2), but at
// a = pi it is inf in double (1 + cos a = 0), where a cone's answer is 4 pi.

// A cone of half-angle a (0 <= a <= pi), i.e. a spherical cap: 2 pi (1 - cos a).
double solidAngleOfCone(double halfAngle);
// A sphere of `radius` seen from `distance` to its centre: the cap of sin a = radius / distance;
// 4 pi when distance <= radius (the point is inside).
double solidAngleOfSphere(double radius, double distance);
// Triangle a, b, c seen from p (Van Oosterom and Strackee 1983), unsigned:
// tan(Omega / 2) = |A . (B x C)| / (|A||B||C| + (A.B)|C| + (A.C)|B| + (B.C)|A|), A = a - p, ...
// Take both signs into account (atan2): Omega exceeds pi when the denominator is negative.
double solidAngleOfTriangle(const DVec3& p, const DVec3& a, const DVec3& b, const DVec3& c);
// The parallelogram corner, corner + u, corner + u + v, corner + v seen from p.
double solidAngleOfRectangle(const DVec3& p, const DVec3& corner, const DVec3& u, const DVec3& v);
// The midpoint rule for the integral of f(theta, phi) dOmega = f sin(theta) dtheta dphi over the
// whole sphere: thetaSteps x phiSteps cells, f and sin(theta) at cell centres
// theta_i = (i + 1/2) pi / thetaSteps, phi_j = (j + 1/2) 2 pi / phiSteps. With f = 1 it tends to
// 4 pi; with f = I it is the flux of a point source of intensity I.
double integrateOverSphere(const std::function<double(double theta, double phi)>& f, int thetaSteps, int phiSteps);

// --- Samplers (assignments/a6_radiometry/samplers.cpp, spherical_triangle.cpp) -------------------
// Directions about +z (turn them with Frame); pdf per steradian, of the returned direction.

// z = 1 - 2 u.x, phi = 2 pi u.y; pdf 1 / (4 pi).
DirectionSample sampleUniformSphere(Vec2 u);
// z = u.x, phi = 2 pi u.y; pdf 1 / (2 pi).
DirectionSample sampleUniformHemisphere(Vec2 u);
// Malley's method: a uniform point on the unit disk, r = sqrt(u.x), phi = 2 pi u.y, lifted to
// z = sqrt(1 - r^2); pdf cos(theta) / pi.
DirectionSample sampleCosineHemisphere(Vec2 u);
// Inside the cone of cos(theta) >= cosThetaMax (< 1): cos(theta) = 1 - u.x (1 - cosThetaMax),
// phi = 2 pi u.y; pdf 1 / (2 pi (1 - cosThetaMax)).
DirectionSample sampleUniformCone(Vec2 u, float cosThetaMax);
// A uniform point of the triangle: s = sqrt(u.x), barycentrics b0 = 1 - s, b1 = u.y s,
// b2 = 1 - b0 - b1 (weights of p0, p1, p2); pdf 1 / area.
PointSample sampleUniformTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u);
// A direction from p, uniform over the solid angle Omega the triangle subtends (Arvo 1995).
// With A, B, C the unit directions from p to p0, p1, p2: u.x picks the spherical triangle
// A, B, C' of area u.x Omega with C' on the arc from A to C, and u.y the point on the arc from
// B to C' whose cosine to B is 1 - u.y (1 - C'.B) (docs/a6-radiometry.md#spherical-triangles).
// pdf 1 / Omega; pdf 0 when the triangle is degenerate seen from p (Omega = 0).
DirectionSample sampleSphericalTriangle(const Vec3& p, const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec2 u);
// A density per unit area at a light point turned into one per steradian at the shading point:
// pdfArea d^2 / |cos(theta_light)|, theta_light between the light's normal and the direction
// to the shading point; infinite for cos(theta_light) = 0.
float areaToSolidAnglePdf(float pdfArea, float distanceSquared, float cosThetaLight);

// --- Estimators of direct light (assignments/a6_radiometry/light_estimators.cpp) ---------------

// Deterministic: albedo/pi * I cos(theta_x) / d^2 when the light is visible.
Vec3 estimatePointLight(const ShadingPoint& x, const PointEmitter& light, const SceneRays& rays);
// Area sampling: y = sampleUniformTriangle(..., u); zero from the back of a one-sided triangle.
Vec3 estimateTriangleLightByArea(const ShadingPoint& x, const TriangleEmitter& light, Vec2 u, const SceneRays& rays);
// Solid-angle sampling: sampleSphericalTriangle(x.position, ..., u); the light point is where
// the direction meets the triangle's plane.
Vec3 estimateTriangleLightBySolidAngle(const ShadingPoint& x, const TriangleEmitter& light, Vec2 u, const SceneRays& rays);
// Area sampling over the whole sphere: y = centre + radius * sampleUniformSphere(u).direction,
// pdf 1 / (4 pi r^2); the far half faces away from x and counts nothing.
Vec3 estimateSphereLightByArea(const ShadingPoint& x, const SphereEmitter& light, Vec2 u, const SceneRays& rays);
// Solid-angle sampling: sampleUniformCone(u, cos(theta_max)) about the direction to the centre,
// sin(theta_max) = radius / d; the light point is where the direction first meets the sphere.
// Nothing reaches a point that is not outside the sphere (d <= radius).
Vec3 estimateSphereLightBySolidAngle(const ShadingPoint& x, const SphereEmitter& light, Vec2 u, const SceneRays& rays);

// --- Estimators by direction (assignments/a6_radiometry/direction_estimators.cpp) --------------
// All emitters at once: a direction about x.normal, and what SceneRays::incomingEmission finds.

Vec3 estimateByUniformHemisphere(const ShadingPoint& x, Vec2 u, const SceneRays& rays);
Vec3 estimateByCosineHemisphere(const ShadingPoint& x, Vec2 u, const SceneRays& rays);

}  // namespace rtlab
