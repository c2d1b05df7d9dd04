// Reference solution: radiometric units (docs/a6-radiometry.md#units).
#include "framework/interface/a6_radiometry.h"

#include <numbers>

namespace rtlab {
namespace {

constexpr double kPi = std::numbers::pi;
// Lumens per watt at 555 nm: the candela's definition fixes the eye's peak efficacy at 683.
constexpr double kLumensPerWatt = 683.0;

}  // namespace

double energyFromPower(double watts, double seconds) { return watts * seconds; }

double powerFromEnergy(double joules, double seconds) { return joules / seconds; }

// An isotropic source spreads its flux evenly over the 4 pi steradians of the sphere.
double intensityFromPower(double watts) { return watts / (4.0 * kPi); }

double powerFromIntensity(double wattsPerSteradian) { return 4.0 * kPi * wattsPerSteradian; }

// The flux into a small patch dA is I dOmega with dOmega = dA cos(theta) / d^2.
double irradianceFromIntensity(double wattsPerSteradian, double distance, double cosTheta) {
    return wattsPerSteradian * cosTheta / (distance * distance);
}

// Integrating L cos(theta) over the hemisphere gives pi L per unit area, times the area.
double radianceFromPower(double watts, double area) { return watts / (kPi * area); }

double powerFromRadiance(double radiance, double area) { return kPi * radiance * area; }

double irradianceFromRadiance(double radiance) { return kPi * radiance; }

double lumensFromWatts(double watts) { return watts * kLumensPerWatt; }

double wattsFromLumens(double lumens) { return lumens / kLumensPerWatt; }

}  // namespace rtlab
