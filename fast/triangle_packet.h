// Four triangles tested against one ray at once: the watertight test of a0 (Woop, Benthin,
// Wald 2013) with its per-ray half done once per ray and its per-triangle half done in four
// SIMD lanes (docs/performance.md, "The wide BVH").
//
// The arithmetic is the a0 reference's (solutions/a0_intersect/ray_triangle.cpp) operation for
// operation, lane by lane, and of several hits the one a loop over the lanes in order would keep
// is returned. So a traversal using packets reports the same hits, bit for bit, as one calling
// intersectTriangle on each triangle. A float screen goes first and only ever rules out lanes
// the exact arithmetic misses too (ShearedRay::surelyOutside).
#pragma once

#include "fast/simd.h"
#include "framework/accel/primitive_set.h"
#include "framework/core/float_bits.h"
#include "framework/core/ray.h"
#include "framework/interface/a0_intersect.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

namespace rtlab {

// The lane of a packet that holds no triangle, and the degenerate triangle it holds.
inline constexpr uint32_t kNoPrimitive = 0xffffffffu;
inline const std::array<Vec3, 3> kNoTriangle{Vec3(0.0f), Vec3(0.0f), Vec3(0.0f)};

// No default initialiser: the wide BVH's packets are allocated uninitialised and filled on
// several threads, each written once (fill); a gatherer sets every lane itself (set, then pad).
struct alignas(16) TrianglePacket {
    static constexpr int kLanes = 4;
    // coordinate[axis][v][lane]: coordinate `axis` of vertex v of the lane's triangle, so one row
    // is one SIMD load, and a ray's test finds the three rows of one axis at fixed distances
    // from each other (three offsets per ray, not nine registers). A lane without a triangle
    // has all three vertices at the origin: a degenerate triangle, whose edge functions are
    // all zero, so no ray hits it.
    float coordinate[3][3][kLanes];
    uint32_t prim[kLanes];

    void set(int lane, uint32_t id, const std::array<Vec3, 3>& triangle) {
        prim[lane] = id;
        for (int v = 0; v < 3; ++v)
            for (int axis = 0; axis < 3; ++axis) coordinate[axis][v][lane] = triangle[v][axis];
    }

    // The lanes after the first `used`: copies of lane used - 1 where that lane holds a triangle,
    // else lanes with no triangle. A copy changes no answer (its hit is its original's: the same
    // id, distance and barycentrics, and the last of equally near lanes either way), but unlike
    // a degenerate lane the test's float screen can rule it out (ShearedRay::test).
    void pad(int used, bool lastIsTriangle) {
        for (int lane = used; lane < kLanes; ++lane) {
            prim[lane] = used > 0 && lastIsTriangle ? prim[used - 1] : kNoPrimitive;
            for (int v = 0; v < 3; ++v)
                for (int axis = 0; axis < 3; ++axis)
                    coordinate[axis][v][lane] = used > 0 && lastIsTriangle ? coordinate[axis][v][used - 1] : 0.0f;
        }
    }

    // Every lane: the primitives' triangles in order, then padding. A sphere keeps its id in a
    // lane with no triangle; the traversal tests it on its own.
    void fill(const PrimitiveSet& primitives, std::span<const uint32_t> prims) {
        const int used = int(prims.size());
        for (int lane = 0; lane < used; ++lane) {
            uint32_t id = prims[lane];
            set(lane, id, id < primitives.triangleCount() ? primitives.triangle(id) : kNoTriangle);
        }
        pad(used, used > 0 && prims[used - 1] < primitives.triangleCount());
    }
};

RTLAB_ISA_NAMESPACE_BEGIN

// The lane of the nearest hit in a packet (-1 for none) and where it is.
struct PacketHit {
    int lane = -1;
    TriangleHit hit;
};

// One ray, prepared for packet tests: the axis that becomes z, the shear that maps the ray
// onto +z, and the origin, each broadcast to all lanes.
class ShearedRay {
    using Lanes = Simd<float, TrianglePacket::kLanes>;
    using Mask = SimdMask<TrianglePacket::kLanes>;

public:
    explicit ShearedRay(const Ray& ray) {
        // Plain arrays: indexing a glm vector by a run-time axis compiles to a switch.
        const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        const float direction[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
        // maxComponentIndex's choice, computed without branches: for incoherent rays which axis
        // is largest is a coin toss, and its branches missed about once per ray.
        const float absX = std::fabs(direction[0]), absY = std::fabs(direction[1]), absZ = std::fabs(direction[2]);
        const int xLargest = (absX >= absY) & (absX >= absZ);
        int kz = (1 - xLargest) * (2 - int(absY >= absZ));
        int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
        axis_ = {kx, ky, kz};
        // a0 reports no hit where dz is 0. That is a zero direction (dz is its largest
        // component), so sx and sy are 0 / 0, NaN, and so is every lane's t, which then fails
        // t > tMin: such a ray needs no test of its own.
        float dz = direction[kz];
        for (int i = 0; i < 3; ++i) negatedOrigin_[i] = broadcastNegated<4>(origin[axis_[i]]);
        sx_ = broadcast<4>(-direction[kx] / dz);
        sy_ = broadcast<4>(-direction[ky] / dz);
        sz_ = broadcast<4>(1.0f / dz);
        tMin_ = broadcast<4>(ray.tMin);
    }

    // The nearest hit with ray.tMin < t <= tMax among the packet's triangles; of equally near
    // ones, the last lane's (a loop over the lanes accepting t <= tMax keeps the last).
    PacketHit closest(const TrianglePacket& packet, float tMax) const {
        LaneHits lanes = test(packet, tMax);
        unsigned hits = laneBits<4>(lanes.hit);
        if (hits == 0) return {};
        int lane = std::countr_zero(hits);
        if (hits & (hits - 1)) {  // several hits: the nearest, the last of equals
            float nearest = minimum(lanes.hit ? lanes.t : broadcast<4>(kInfinity));
            lane = std::bit_width(hits & laneBits<4>(lanes.t == broadcast<4>(nearest))) - 1;
        }
        return {lane, TriangleHit{lanes.t[lane], lanes.b1[lane], lanes.b2[lane]}};
    }

    // Whether any of the packet's triangles is hit with ray.tMin < t <= tMax.
    bool anyHit(const TrianglePacket& packet, float tMax) const { return laneBits<4>(test(packet, tMax).hit) != 0; }

private:
    struct LaneHits {
        Lanes t, b1, b2;
        Mask hit;

        static LaneHits none() { return {Lanes{}, Lanes{}, Lanes{}, Mask{}}; }
    };

    // The test itself, lane by lane: which lanes are hit, and where.
    LaneHits test(const TrianglePacket& packet, float tMax) const {
        // Vertex coordinates relative to the ray origin, in the permuted axes (x, y, z) = (kx,
        // ky, kz): a row load each.
        Lanes a[3], b[3], c[3];
        for (int i = 0; i < 3; ++i) {
            a[i] = load<4>(packet.coordinate[axis_[i]][0]) + negatedOrigin_[i];
            b[i] = load<4>(packet.coordinate[axis_[i]][1]) + negatedOrigin_[i];
            c[i] = load<4>(packet.coordinate[axis_[i]][2]) + negatedOrigin_[i];
        }
        Lanes ax = a[0] + sx_ * a[2], ay = a[1] + sy_ * a[2];
        Lanes bx = b[0] + sx_ * b[2], by = b[1] + sy_ * b[2];
        Lanes cx = c[0] + sx_ * c[2], cy = c[1] + sy_ * c[2];

        // Most triangles a ray is tested against lie clearly beside it. A screen in float finds
        // those lanes, and when it finds all four the exact edge functions (in double) are not
        // needed. Everything else is decided by the exact arithmetic alone, so the answers are
        // the same with or without the screen.
        if (laneBits<4>(surelyOutside(bx, cy, by, cx, cx, ay, cy, ax, ax, by, ay, bx)) == 0xfu) return LaneHits::none();
        Lanes e0 = differenceOfProducts(bx, cy, by, cx);
        Lanes e1 = differenceOfProducts(cx, ay, cy, ax);
        Lanes e2 = differenceOfProducts(ax, by, ay, bx);
        const Lanes zero{};
        Mask anyNegative = (e0 < zero) | (e1 < zero) | (e2 < zero);
        Mask anyPositive = (e0 > zero) | (e1 > zero) | (e2 > zero);
        Lanes det = e0 + e1 + e2;

        Lanes az = sz_ * a[2], bz = sz_ * b[2], cz = sz_ * c[2];
        Lanes invDet = broadcast<4>(1.0f) / det;
        Lanes t = (e0 * az + e1 * bz + e2 * cz) * invDet;
        // Written so that NaN fails: det != 0 is true for NaN, but then t is NaN. t - t is 0
        // exactly when t is finite.
        Mask hit = ~(anyNegative & anyPositive) & (det != zero) & (t > tMin_) & (t <= broadcast<4>(tMax)) &
                   ((t - t) == zero);
        return {t, e1 * invDet, e2 * invDet, hit};
    }

    // The float screen: lanes where, of the three exact edge functions a*b - c*d, one is surely
    // negative and another surely positive, so that the exact test misses too. In float, with
    // p = a*b and q = c*d rounded:
    //  * the sign of p - q is never wrong. Rounding is monotonic, so a*b < c*d gives p <= q, and
    //    p < q only if a*b < c*d. This needs p and q rounded before the subtraction: fused into
    //    one FMA, a*b - q can have the wrong sign, hence roundedAsIs.
    //  * it can be tiny where the exact value, rounded to float, is 0 (products that
    //    underflow). |p - q| > 2^-60 rules that out: then p or q is above 2^-62, and a*b and
    //    c*d, if not equal, differ by at least 2^-110, which stays nonzero as a float.
    // Infinite and NaN values compare false: not ruled out.
    //
    // One edge negative and another positive is the smallest of the three values below -floor
    // and the largest above floor (a MINPS and a MAXPS each, not six comparisons). Each ?: keeps
    // one of its operands, so a smallest below -floor is an edge's own value; a NaN can only
    // hide a sign, and so leave a lane to the exact test, never rule one out.
    static Mask surelyOutside(Lanes a0, Lanes b0, Lanes c0, Lanes d0, Lanes a1, Lanes b1, Lanes c1, Lanes d1,
                              Lanes a2, Lanes b2, Lanes c2, Lanes d2) {
        auto value = [](Lanes a, Lanes b, Lanes c, Lanes d) { return roundedAsIs(a * b) - roundedAsIs(c * d); };
        const Lanes v0 = value(a0, b0, c0, d0), v1 = value(a1, b1, c1, d1), v2 = value(a2, b2, c2, d2);
        Lanes smallest = v1 < v0 ? v1 : v0, largest = v1 > v0 ? v1 : v0;
        smallest = v2 < smallest ? v2 : smallest;
        largest = v2 > largest ? v2 : largest;
        const Lanes floor = broadcast<4>(0x1p-60f);
        return (smallest < -floor) & (largest > floor);
    }

    // a*b - c*d per lane with the exact sign, as float_bits.h's differenceOfProducts: the
    // products are exact in double.
    static Lanes differenceOfProducts(Lanes a, Lanes b, Lanes c, Lanes d) {
        using Doubles = Simd<double, 4>;
#if defined(__AVX__)
        // One VCVTPS2PD per operand. GCC 12 makes __builtin_convertvector two conversions of
        // halves, the upper one through memory: 18 more instructions per exact test.
        Doubles ab = __builtin_ia32_cvtps2pd256(a) * __builtin_ia32_cvtps2pd256(b);
        Doubles cd = __builtin_ia32_cvtps2pd256(c) * __builtin_ia32_cvtps2pd256(d);
#else
        Doubles ab = __builtin_convertvector(a, Doubles) * __builtin_convertvector(b, Doubles);
        Doubles cd = __builtin_convertvector(c, Doubles) * __builtin_convertvector(d, Doubles);
#endif
        return __builtin_convertvector(ab - cd, Lanes);
    }

    static float minimum(Lanes v) {
        Lanes swapped = __builtin_shuffle(v, Mask{2, 3, 0, 1});
        v = swapped < v ? swapped : v;
        swapped = __builtin_shuffle(v, Mask{1, 0, 3, 2});
        v = swapped < v ? swapped : v;
        return v[0];
    }

    std::array<int, 3> axis_;
    Lanes negatedOrigin_[3];  // see broadcastNegated
    Lanes sx_, sy_, sz_;
    Lanes tMin_;
};

RTLAB_ISA_NAMESPACE_END
}  // namespace rtlab
