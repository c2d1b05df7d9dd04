// a6's functions on the grader's inputs: units, solid angles and the sphere integral one call at
// a time; samplers on given u, and samplers and estimators `count` times on uniform numbers
// drawn here from the call's seed (PCG32, stream = the call's index), returning every sample
// raw. The estimators' shadow and emitter rays go to the exact oracle, so a6 is graded without
// any other assignment's code.
#include "framework/core/pcg32.h"
#include "framework/interface/a6_radiometry.h"
#include "grader/a6_radiometry/wire/sample_calls.h"
#include "grader/a6_radiometry/wire/radiometry_inputs.h"
#include "framework/render/oracle_rays.h"
#include "grader/wire/scene_codec.h"
#include "grader/worker/worker_tasks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace rtlab::grader::worker {
namespace {

constexpr uint64_t kMaxCalls = uint64_t(1) << 16;
constexpr int32_t kMaxIntegralSteps = 1 << 14;

double callUnit(const UnitCall& c) {
    switch (c.function) {
        case UnitFunction::EnergyFromPower: return energyFromPower(c.a, c.b);
        case UnitFunction::PowerFromEnergy: return powerFromEnergy(c.a, c.b);
        case UnitFunction::IntensityFromPower: return intensityFromPower(c.a);
        case UnitFunction::PowerFromIntensity: return powerFromIntensity(c.a);
        case UnitFunction::IrradianceFromIntensity: return irradianceFromIntensity(c.a, c.b, c.c);
        case UnitFunction::RadianceFromPower: return radianceFromPower(c.a, c.b);
        case UnitFunction::PowerFromRadiance: return powerFromRadiance(c.a, c.b);
        case UnitFunction::IrradianceFromRadiance: return irradianceFromRadiance(c.a);
        case UnitFunction::LumensFromWatts: return lumensFromWatts(c.a);
        case UnitFunction::WattsFromLumens: return wattsFromLumens(c.a);
    }
    throw WireError("an unknown unit function");
}

double callSolidAngle(const SolidAngleCall& c) {
    switch (c.function) {
        case SolidAngleFunction::Cone: return solidAngleOfCone(c.x);
        case SolidAngleFunction::Sphere: return solidAngleOfSphere(c.x, c.y);
        case SolidAngleFunction::Triangle: return solidAngleOfTriangle(c.p, c.a, c.b, c.c);
        case SolidAngleFunction::Rectangle: return solidAngleOfRectangle(c.p, c.a, c.b, c.c);
    }
    throw WireError("an unknown solid angle function");
}

std::function<double(double, double)> integrand(Integrand which) {
    switch (which) {
        case Integrand::One: return [](double, double) { return 1.0; };
        case Integrand::PositiveCosine: return [](double theta, double) { return std::max(0.0, std::cos(theta)); };
        case Integrand::OnePlusCosPhi: return [](double, double phi) { return 1.0 + std::cos(phi); };
    }
    throw WireError("an unknown integrand");
}


void runUnits(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const UnitCall& call : input.getVector<UnitCall>(kMaxCalls)) output.put<double>(callUnit(call));
}

void runSolidAngles(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const SolidAngleCall& call : input.getVector<SolidAngleCall>(kMaxCalls)) output.put<double>(callSolidAngle(call));
}

void runSphereIntegrals(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const IntegralCall& call : input.getVector<IntegralCall>(kMaxCalls)) {
        if (call.thetaSteps < 1 || call.phiSteps < 1 || call.thetaSteps > kMaxIntegralSteps || call.phiSteps > kMaxIntegralSteps)
            throw WireError("bad integration steps");
        output.put<double>(integrateOverSphere(integrand(call.integrand), call.thetaSteps, call.phiSteps));
    }
}

void runSamples(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto call = input.get<SamplerCall>();
    if (call.count > kMaxSamplesPerCall) throw WireError("too many samples");
    Pcg32 rng(call.seed, 0);
    output.put<uint64_t>(call.count);
    for (uint32_t i = 0; i < call.count; ++i) output.put(sampleOnce(call, uniformPair(rng)));
}

void runSamplesAt(ByteReader& input, ByteWriter& output, WorkerState&) {
    auto call = input.get<SamplerCall>();
    std::vector<Vec2> given = input.getVector<Vec2>(kMaxCalls);
    output.put<uint64_t>(given.size());
    for (Vec2 u : given) output.put(sampleOnce(call, u));
}

void runPdfConversions(ByteReader& input, ByteWriter& output, WorkerState&) {
    for (const PdfCall& call : input.getVector<PdfCall>(kMaxCalls))
        output.put<float>(areaToSolidAnglePdf(call.pdfArea, call.distanceSquared, call.cosThetaLight));
}

void runEstimates(ByteReader& input, ByteWriter& output, WorkerState& state) {
    auto cases = input.get<uint64_t>();
    if (cases > kMaxCalls) throw WireError("too many estimator cases");
    for (uint64_t k = 0; k < cases; ++k) {
        state.scene = readScene(input);
        auto call = input.get<EstimatorCall>();
        if (call.count > kMaxSamplesPerCall) throw WireError("too many samples");
        Oracle oracle(state.scene);
        OracleRays rays(state.scene, oracle, call.point.position);
        Pcg32 rng(call.seed, k);
        output.put<uint64_t>(call.count);
        for (uint32_t i = 0; i < call.count; ++i) output.put(estimateSample(call, uniformPair(rng), rays));
    }
}

const TaskRegistration registration{{kTaskUnits, runUnits},         {kTaskSolidAngles, runSolidAngles},
                                    {kTaskSphereIntegrals, runSphereIntegrals}, {kTaskSamples, runSamples},
                                    {kTaskSamplesAt, runSamplesAt},
                                    {kTaskPdfConversions, runPdfConversions}, {kTaskEstimates, runEstimates}};

}  // namespace

}  // namespace rtlab::grader::worker
