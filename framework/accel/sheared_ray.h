// The watertight ray-triangle test (Woop, Benthin, Wald 2013) with its per-ray half done once
// per ray, as the paper intends: which axis becomes z and the shear that maps the ray onto +z
// depend on the ray alone. Each triangle then costs three subtractions, a 2D transform, three
// exact edge functions and one division.
//
// The arithmetic is the a0 reference's (solutions/a0_intersect/ray_triangle.cpp) operation for
// operation, so a traversal using it reports the same hits, bit for bit, as one calling
// intersectTriangle.
#pragma once

#include "framework/core/float_bits.h"
#include "framework/core/ray.h"
#include "framework/interface/a0_intersect.h"

#include <array>
#include <cmath>

namespace rtlab {

// A triangle's vertices as plain coordinates, indexed by an axis chosen per ray.
using TriangleCoordinates = std::array<std::array<float, 3>, 3>;

inline TriangleCoordinates coordinatesOf(const std::array<Vec3, 3>& p) {
    return {{{p[0].x, p[0].y, p[0].z}, {p[1].x, p[1].y, p[1].z}, {p[2].x, p[2].y, p[2].z}}};
}

class ShearedRay {
public:
    explicit ShearedRay(const Ray& ray) : origin_{ray.origin.x, ray.origin.y, ray.origin.z}, tMin_(ray.tMin) {
        kz_ = maxComponentIndex(glm::abs(ray.direction));
        kx_ = (kz_ + 1) % 3;
        ky_ = (kx_ + 1) % 3;
        float dz = ray.direction[kz_];
        valid_ = dz != 0.0f;  // false for a zero-length or NaN direction
        sx_ = -ray.direction[kx_] / dz;
        sy_ = -ray.direction[ky_] / dz;
        sz_ = 1.0f / dz;
    }

    // True when the ray hits the triangle at some t with ray.tMin < t <= tMax; then fills *hit.
    bool intersect(const TriangleCoordinates& p, float tMax, TriangleHit* hit) const {
        if (!valid_) return false;
        // Vertex coordinates relative to the ray origin, in the permuted axes (x, y, z) =
        // (kx, ky, kz); only these nine differences are needed.
        float a[3], b[3], c[3];
        for (int i = 0; i < 3; ++i) {
            int k = i == 0 ? kx_ : i == 1 ? ky_ : kz_;
            a[i] = p[0][k] - origin_[k];
            b[i] = p[1][k] - origin_[k];
            c[i] = p[2][k] - origin_[k];
        }
        float ax = a[0] + sx_ * a[2], ay = a[1] + sy_ * a[2];
        float bx = b[0] + sx_ * b[2], by = b[1] + sy_ * b[2];
        float cx = c[0] + sx_ * c[2], cy = c[1] + sy_ * c[2];

        float e0 = differenceOfProducts(bx, cy, by, cx);
        float e1 = differenceOfProducts(cx, ay, cy, ax);
        float e2 = differenceOfProducts(ax, by, ay, bx);
        // Mixed signs: the ray passes outside. Evaluated without short-circuits, as one branch.
        bool anyNegative = (e0 < 0) | (e1 < 0) | (e2 < 0), anyPositive = (e0 > 0) | (e1 > 0) | (e2 > 0);
        if (anyNegative & anyPositive) return false;
        float det = e0 + e1 + e2;
        if (!(det != 0.0f)) return false;

        float az = sz_ * a[2], bz = sz_ * b[2], cz = sz_ * c[2];
        float invDet = 1.0f / det;
        float t = (e0 * az + e1 * bz + e2 * cz) * invDet;
        if (!(t > tMin_ && t <= tMax) || !std::isfinite(t)) return false;
        *hit = TriangleHit{t, e1 * invDet, e2 * invDet};
        return true;
    }

private:
    float origin_[3];
    float tMin_;
    int kx_, ky_, kz_;
    float sx_, sy_, sz_;
    bool valid_;
};

}  // namespace rtlab
