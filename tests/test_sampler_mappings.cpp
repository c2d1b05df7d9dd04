// grader/a6_radiometry/sampler_mappings: the pinned mappings the grader checks samples against, computed from
// their definitions, against closed forms derived by hand and against the reference samplers
// (Arvo's closed form for spherical triangles, a formula of its own).
#include "framework/core/pcg32.h"
#include "framework/interface/a6_radiometry.h"
#include "grader/a6_radiometry/sampler_mappings.h"
#include "grader/a6_radiometry/wire/sample_calls.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace rtlab;
using namespace rtlab::grader;
using worker::Sampler;

namespace {

worker::SamplerCall configured(Sampler sampler) {
    worker::SamplerCall c{};
    c.sampler = sampler;
    c.cosThetaMax = 0.3f;
    c.p = {0.2f, -0.1f, 0.05f}, c.p0 = {-0.5f, -0.4f, 1.0f}, c.p1 = {0.1f, 0.7f, 0.9f}, c.p2 = {0.6f, -0.3f, 1.2f};
    return c;
}

// What the reference sampler (solutions/a6_radiometry) returns for u.
DVec3 reference(const worker::SamplerCall& c, Vec2 u) { return DVec3(worker::sampleOnce(c, u).value); }

}  // namespace

TEST_CASE("sampler mappings: the spherical triangle's, by bisection, is the octant's closed form") {
    // The octant seen from its corner: B = +y is the pole of the great circle through A = +x and
    // C = +z, so the sub-triangle A, B, C' has area t where C' is at the angle t from A; u.x of
    // the octant's pi/2 puts C' at u.x pi/2, and C' . B = 0 makes the cosine to B 1 - u.y.
    worker::SamplerCall c{};
    c.sampler = Sampler::SphericalTriangle;
    c.p = {1, 2, 3}, c.p0 = {4, 2, 3}, c.p1 = {1, 5, 3}, c.p2 = {1, 2, 6};
    Pcg32 rng(7, 0);
    for (int i = 0; i < 200; ++i) {
        Vec2 u = worker::uniformPair(rng);
        double z = 1.0 - u.y, r = std::sqrt(1.0 - z * z), t = u.x * std::numbers::pi / 2.0;
        DVec3 expected(r * std::cos(t), z, r * std::sin(t));
        CAPTURE(u.x);
        CAPTURE(u.y);
        CHECK(glm::length(pinnedSample(c, u) - expected) < 1e-9);
    }
}

TEST_CASE("sampler mappings: every pinned mapping is the reference sampler's, far inside the tolerance") {
    for (Sampler s : {Sampler::UniformSphere, Sampler::UniformHemisphere, Sampler::CosineHemisphere, Sampler::UniformCone, Sampler::UniformTriangle,
                      Sampler::SphericalTriangle}) {
        worker::SamplerCall c = configured(s);
        CAPTURE(static_cast<int>(s));
        Pcg32 rng(11, static_cast<uint64_t>(s));
        double worst = 0.0;
        for (int i = 0; i < 20000; ++i) {
            Vec2 u = worker::uniformPair(rng);
            worst = std::max(worst, glm::length(pinnedSample(c, u) - reference(c, u)));
        }
        // Float rounding of the reference: near a pole sqrt(1 - z^2) in float moves a direction
        // by up to about 5e-4 (the tolerance's reason), elsewhere by about 1e-6.
        CHECK(worst < 0.5 * pinnedTolerance(c));
    }
}

TEST_CASE("sampler mappings: another mapping of the same distribution is far outside the tolerance") {
    // z = 2 u.x - 1 draws the same uniform sphere as the pinned z = 1 - 2 u.x, and u.y mirrored
    // the same uniform azimuth: the distribution cannot tell them apart, the mapping can.
    worker::SamplerCall c = configured(Sampler::UniformSphere);
    Pcg32 rng(13, 0);
    int far = 0;
    for (int i = 0; i < 1000; ++i) {
        Vec2 u = worker::uniformPair(rng);
        if (glm::length(pinnedSample(c, u) - pinnedSample(c, Vec2(1.0f - u.x, u.y))) > pinnedTolerance(c)) ++far;
    }
    CHECK(far > 990);
}
