#include "grader/a6_radiometry/a6_tests.h"

namespace rtlab::grader {

const StubTable& a6Stubs() {
    static const StubTable table{"a6", "a6_radiometry", {
        {"direction_estimators.cpp", {"estimateByUniformHemisphere", "estimateByCosineHemisphere"}},
        {"light_estimators.cpp", {"estimatePointLight", "estimateTriangleLightByArea", "estimateTriangleLightBySolidAngle", "estimateSphereLightByArea", "estimateSphereLightBySolidAngle"}},
        {"samplers.cpp", {"sampleUniformSphere", "sampleUniformHemisphere", "sampleCosineHemisphere", "sampleUniformCone", "sampleUniformTriangle", "areaToSolidAnglePdf"}},
        {"solid_angle.cpp", {"solidAngleOfCone", "solidAngleOfSphere", "solidAngleOfTriangle", "solidAngleOfRectangle", "integrateOverSphere"}},
        {"spherical_triangle.cpp", {"sampleSphericalTriangle"}},
        {"units.cpp", {"energyFromPower", "powerFromEnergy", "intensityFromPower", "powerFromIntensity", "irradianceFromIntensity", "radianceFromPower", "powerFromRadiance", "irradianceFromRadiance", "lumensFromWatts", "wattsFromLumens"}},
    }};
    return table;
}

}  // namespace rtlab::grader
