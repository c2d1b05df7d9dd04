// Assignment a6, part 1: radiometric units.         Guide: docs/a6-radiometry.md#units
//
// Contract (framework/interface/a6_radiometry.h), in double, SI units:
//   energyFromPower      Q = Phi t              powerFromEnergy     Phi = Q / t
//   intensityFromPower   I = Phi / (4 pi)       powerFromIntensity  Phi = 4 pi I   (isotropic)
//   irradianceFromIntensity   E = I cos(theta) / d^2
//   radianceFromPower    L = Phi / (pi A)       powerFromRadiance   Phi = pi L A   (one-sided
//                                                                   Lambertian emitter)
//   irradianceFromRadiance    E = pi L  (the same radiance from the whole hemisphere)
//   lumensFromWatts / wattsFromLumens: 683 lm per W (at 555 nm)
//
// Hints:
//   * Where does pi come from in pi L? Integrate L cos(theta) dOmega over the hemisphere
//     with dOmega = sin(theta) dtheta dphi.
//   * std::numbers::pi (<numbers>) is pi in double.
#include "framework/core/error.h"
#include "framework/interface/a6_radiometry.h"

namespace rtlab {

double energyFromPower(double, double) { throw NotImplemented("a6 energyFromPower (assignments/a6_radiometry/units.cpp)"); }
double powerFromEnergy(double, double) { throw NotImplemented("a6 powerFromEnergy (assignments/a6_radiometry/units.cpp)"); }
double intensityFromPower(double) { throw NotImplemented("a6 intensityFromPower (assignments/a6_radiometry/units.cpp)"); }
double powerFromIntensity(double) { throw NotImplemented("a6 powerFromIntensity (assignments/a6_radiometry/units.cpp)"); }
double irradianceFromIntensity(double, double, double) { throw NotImplemented("a6 irradianceFromIntensity (assignments/a6_radiometry/units.cpp)"); }
double radianceFromPower(double, double) { throw NotImplemented("a6 radianceFromPower (assignments/a6_radiometry/units.cpp)"); }
double powerFromRadiance(double, double) { throw NotImplemented("a6 powerFromRadiance (assignments/a6_radiometry/units.cpp)"); }
double irradianceFromRadiance(double) { throw NotImplemented("a6 irradianceFromRadiance (assignments/a6_radiometry/units.cpp)"); }
double lumensFromWatts(double) { throw NotImplemented("a6 lumensFromWatts (assignments/a6_radiometry/units.cpp)"); }
double wattsFromLumens(double) { throw NotImplemented("a6 wattsFromLumens (assignments/a6_radiometry/units.cpp)"); }

}  // namespace rtlab
