// The inputs and outputs of a6's worker tasks (grader/a6_radiometry/worker/radiometry_tasks.cpp): the
// arguments the student's functions are called with, or a seed and a count for the uniform
// numbers (PCG32, stream = the call's index) a sampler or an estimator draws from; never the
// answers the grader expects.
#pragma once

#include "framework/core/fnv1a.h"
#include "framework/core/pcg32.h"
#include "framework/interface/radiometry.h"

#include <cstdint>
#include <type_traits>

namespace rtlab::grader::worker {

inline constexpr const char* kTaskUnits = "a6-units";                // [UnitCall] -> per call f64
inline constexpr const char* kTaskSolidAngles = "a6-solid-angles";   // [SolidAngleCall] -> per call f64
inline constexpr const char* kTaskSphereIntegrals = "a6-integrals";  // [IntegralCall] -> per call f64
inline constexpr const char* kTaskSamples = "a6-samples";            // SamplerCall -> count x (Vec3, f32 pdf)
inline constexpr const char* kTaskSamplesAt = "a6-samples-at";       // SamplerCall, [Vec2 u] -> per u (Vec3, f32 pdf)
inline constexpr const char* kTaskPdfConversions = "a6-pdf";         // [PdfCall] -> per call f32
inline constexpr const char* kTaskEstimates = "a6-estimates";        // [scene, EstimatorCall] -> per call count x Vec3

// The most samples one call may ask for (16 MB of results at 16 bytes each).
inline constexpr uint32_t kMaxSamplesPerCall = 1u << 21;

enum class UnitFunction : uint8_t {
    EnergyFromPower, PowerFromEnergy, IntensityFromPower, PowerFromIntensity, IrradianceFromIntensity,
    RadianceFromPower, PowerFromRadiance, IrradianceFromRadiance, LumensFromWatts, WattsFromLumens
};
struct UnitCall {
    UnitFunction function;
    double a, b, c;  // the arguments in the order of the declaration; the rest unused
};

enum class SolidAngleFunction : uint8_t { Cone, Sphere, Triangle, Rectangle };
struct SolidAngleCall {
    SolidAngleFunction function;
    double x, y;        // Cone: half-angle x; Sphere: radius x, distance y
    DVec3 p, a, b, c;   // Triangle: p, a, b, c; Rectangle: p, corner a, edges b and c
};

// The integrands of integrateOverSphere the grader asks for (f(theta, phi)).
enum class Integrand : uint8_t { One, PositiveCosine, OnePlusCosPhi };
struct IntegralCall {
    Integrand integrand;
    int32_t thetaSteps, phiSteps;
};

enum class Sampler : uint8_t { UniformSphere, UniformHemisphere, CosineHemisphere, UniformCone, UniformTriangle, SphericalTriangle };
struct SamplerCall {
    Sampler sampler;
    float cosThetaMax;        // UniformCone
    Vec3 p, p0, p1, p2;       // UniformTriangle: p0, p1, p2; SphericalTriangle: all
    uint64_t seed;
    uint32_t count;
};
struct SampleResult {
    Vec3 value;  // the direction, or the point of UniformTriangle
    float pdf;
};

// The seed of one call's uniform numbers: FNV-1a over the grading seed, the kind of call and its
// index, so that neighbouring grading seeds, kinds and indices give unrelated PCG32 streams.
inline uint64_t callSeed(uint64_t gradingSeed, uint64_t kind, uint64_t index) {
    const uint64_t words[3] = {gradingSeed, kind, index};
    return fnv1a64(words, sizeof words);
}

// The pair of uniform numbers a sampler or an estimator gets, u.x drawn first: the worker draws
// them, the grader replays them to check each sample against the u it came from.
inline Vec2 uniformPair(Pcg32& rng) {
    float x = rng.uniform();
    return Vec2(x, rng.uniform());
}

struct PdfCall {
    float pdfArea, distanceSquared, cosThetaLight;
};

enum class Estimator : uint8_t {
    PointLight, TriangleByArea, TriangleBySolidAngle, SphereByArea, SphereBySolidAngle, UniformHemisphere, CosineHemisphere
};
// One estimator at one shading point, `count` samples (PointLight: one); the light it needs.
// The scene sent before it holds the lights as emissive geometry and any occluders: the
// worker's SceneRays answer with the exact oracle.
struct EstimatorCall {
    Estimator estimator;
    ShadingPoint point;
    PointEmitter pointLight;
    TriangleEmitter triangle;
    SphereEmitter sphere;
    uint64_t seed;
    uint32_t count;
};

static_assert(std::is_trivially_copyable_v<UnitCall> && std::is_trivially_copyable_v<SolidAngleCall> &&
              std::is_trivially_copyable_v<IntegralCall> && std::is_trivially_copyable_v<SamplerCall> &&
              std::is_trivially_copyable_v<SampleResult> && std::is_trivially_copyable_v<PdfCall> &&
              std::is_trivially_copyable_v<EstimatorCall>);

}  // namespace rtlab::grader::worker
