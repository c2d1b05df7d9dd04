// The data of assignment a6 (docs/a6-radiometry.md): what a sampler returns, the lights an
// estimator is given, the point it shades, and the two questions it may ask the scene.
// Units: W (flux), W/sr (intensity), W/m^2 (irradiance), W/(m^2 sr) (radiance), per RGB channel.
#pragma once

#include "framework/core/vec.h"

#include <cmath>

namespace rtlab {

// A direction drawn by a sampler and the density it was drawn with, per steradian.
struct DirectionSample {
    Vec3 direction{0.0f, 0.0f, 1.0f};  // unit length
    float pdf = 0.0f;                   // [1/sr]
};

// A point drawn on a surface and the density it was drawn with, per unit area.
struct PointSample {
    Vec3 point{0.0f};
    float pdf = 0.0f;  // [1/m^2]
};

// An isotropic point light: the same intensity in every direction.
struct PointEmitter {
    Vec3 position{0.0f};
    Vec3 intensity{0.0f};  // [W/sr]
};

// One triangle of an emissive mesh: uniform radiance on its front side, the side its normal
// (p1 - p0) x (p2 - p0) points to (counter-clockwise seen from the front), or on both sides.
struct TriangleEmitter {
    Vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};
    Vec3 radiance{0.0f};  // [W/(m^2 sr)]
    bool twoSided = false;
};

// An emissive sphere: uniform radiance leaving its surface outwards.
struct SphereEmitter {
    Vec3 centre{0.0f};
    float radius = 1.0f;
    Vec3 radiance{0.0f};  // [W/(m^2 sr)]
};

// The surface point an estimator shades: a Lambertian reflector, BRDF albedo / pi.
struct ShadingPoint {
    Vec3 position{0.0f};
    Vec3 normal{0.0f, 0.0f, 1.0f};  // unit, on the side the point is seen from
    Vec3 albedo{0.0f};
};

// What an estimator may ask the scene about the point it shades, one ray per question. The
// renderer answers with its accelerator (your BVH or grid with --accel): `visible` is an any-hit
// query (a shadow ray), `incomingEmission` a closest-hit query. Both rays leave the surface by
// its rounding-error bound and ignore the last 1e-4 of their length (docs/conventions.md,
// "Secondary rays"), so an estimator never offsets anything itself.
class SceneRays {
public:
    virtual ~SceneRays() = default;
    // True when nothing blocks the segment from the shading point to `target` (a point on a
    // light: the light's own surface there does not block it).
    virtual bool visible(const Vec3& target) const = 0;
    // The radiance arriving at the shading point from `direction` (unit, pointing away from the
    // point): the emission of the first surface the ray meets when its emitting side faces the
    // point, else zero (no surface, a surface that does not emit, the back of a one-sided one).
    virtual Vec3 incomingEmission(const Vec3& direction) const = 0;
};

// An orthonormal frame around a unit vector: samplers work about +z, and toWorld turns their
// directions so that +z becomes `axis` (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 2017: continuous everywhere but at axis.z = -0 exactly).
struct Frame {
    Vec3 x, y, z;

    explicit Frame(const Vec3& axis) : z(axis) {
        float sign = std::copysign(1.0f, axis.z);
        float a = -1.0f / (sign + axis.z);
        float b = axis.x * axis.y * a;
        x = Vec3(1.0f + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
        y = Vec3(b, sign + axis.y * axis.y * a, -axis.y);
    }
    Vec3 toWorld(const Vec3& local) const { return local.x * x + local.y * y + local.z * z; }
};

}  // namespace rtlab
