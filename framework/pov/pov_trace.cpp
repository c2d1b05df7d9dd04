#include "framework/pov/pov_trace.h"

#include "framework/core/error.h"
#include "framework/core/pcg32.h"
#include "framework/pov/pov_exporter.h"
#include "framework/pov/pov_format.h"
#include "framework/pov/povray_process.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace rtlab {
namespace fs = std::filesystem;

namespace {

DVec3 uniformDirection(Pcg32& rng) {
    double z = 1.0 - 2.0 * rng.uniform();
    double phi = 2.0 * std::numbers::pi * rng.uniform();
    double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

DVec3 pointIn(const Bounds3f& bounds, Pcg32& rng) {
    DVec3 lower(bounds.lower), upper(bounds.upper);
    return lower + DVec3(rng.uniform(), rng.uniform(), rng.uniform()) * (upper - lower);
}

DVec3 pointOnPrimitive(const Scene& scene, uint32_t prim, Pcg32& rng) {
    if (scene.isSphere(prim)) {
        const Sphere& s = scene.sphere(prim);
        return DVec3(s.centre) + double(s.radius) * uniformDirection(rng);
    }
    auto v = scene.triangleVertices(prim);
    double u1 = rng.uniform(), u2 = rng.uniform();
    double su = std::sqrt(u1);  // uniform over the triangle
    double b1 = su * (1.0 - u2), b2 = su * u2;
    return (1.0 - b1 - b2) * DVec3(v[0]) + b1 * DVec3(v[1]) + b2 * DVec3(v[2]);
}

OracleRay unitRay(const DVec3& origin, const DVec3& direction) {
    OracleRay ray{origin, glm::normalize(direction)};
    ray.tMin = kPovTraceMinDistance;
    return ray;
}

double sceneSize(const Scene& scene) {
    Bounds3f bounds = scene.bounds();
    return bounds.isEmpty() ? 1.0 : std::max(1.0, glm::length(DVec3(bounds.diagonal())));
}

// The SDL program: read the rays, trace each, write point and normal with 17 decimals
// (a bare #write of a float keeps only 6 digits). A miss gives point = normal = <0,0,0>.
constexpr const char* kTraceProgram = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "geometry.inc"
#fopen RayFile "rays.txt" read
#fopen HitFile "hits.txt" write
#read (RayFile, RayCount)
#for (K, 0, RayCount - 1)
  #read (RayFile, Origin, Direction)
  #declare Normal = <0, 0, 0>;
  #declare Point = trace(RtlabScene, Origin, Direction, Normal);
  #write (HitFile, vstr(3, Point, ",", 0, 17), ",", vstr(3, Normal, ",", 0, 17), "\n")
#end
#fclose RayFile
#fclose HitFile
camera { location -z look_at 0 }
)";

void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) throw Error(path.string() + ": cannot write");
}

}  // namespace

std::vector<OracleRay> makeHitSetRays(const Scene& scene, const Camera& camera, size_t count, uint64_t seed) {
    if (scene.primitiveCount() == 0) return {};
    Pcg32 rng(seed, 0x9a7b5c3d);
    Bounds3f bounds = scene.bounds();
    Vec3 margin = 0.1f * bounds.diagonal() + Vec3(1e-3f);
    Bounds3f around(bounds.lower - margin, bounds.upper + margin);
    constexpr int kWidth = 640, kHeight = 480;  // camera rays through pixel centres of this grid

    std::vector<OracleRay> rays;
    rays.reserve(count);
    for (size_t k = 0; k < count; ++k) {
        switch (k % 3) {
            case 0: {
                int i = static_cast<int>(rng.next() % kWidth), j = static_cast<int>(rng.next() % kHeight);
                Ray ray = camera.generateRay(i, j, kWidth, kHeight);
                rays.push_back(unitRay(DVec3(ray.origin), DVec3(ray.direction)));
                break;
            }
            case 1: {
                DVec3 origin = pointIn(around, rng);
                uint32_t prim = rng.next() % scene.primitiveCount();
                DVec3 target = pointOnPrimitive(scene, prim, rng);
                if (glm::length(target - origin) == 0.0) target += DVec3(1.0, 0.0, 0.0);
                rays.push_back(unitRay(origin, target - origin));
                break;
            }
            default:
                rays.push_back(unitRay(pointIn(around, rng), uniformDirection(rng)));
                break;
        }
    }
    return rays;
}

std::vector<PovTraceHit> traceWithPovray(const Scene& scene, const std::vector<OracleRay>& rays) {
    if (rays.empty()) return {};
    TemporaryDirectory work("rtlab-povray-trace");
    writeFile(work.path() / "geometry.inc", exportPovTraceObject(scene, "RtlabScene"));
    std::ostringstream rayText;
    rayText << rays.size() << ",\n";
    for (const OracleRay& ray : rays)
        rayText << pov::vector(ray.origin) << "," << pov::vector(ray.direction) << ",\n";
    writeFile(work.path() / "rays.txt", rayText.str());
    writeFile(work.path() / "hits.pov", kTraceProgram);

    // The 1x1 render is irrelevant: all the work happens while parsing.
    runPovrayOrThrow({"-Ihits.pov", "+W1", "+H1", "-D", "-A", "-Ohits.png"}, work,
                     "tracing rays for " + scene.sourcePath);

    std::ifstream in(work.path() / "hits.txt");
    std::vector<PovTraceHit> hits;
    hits.reserve(rays.size());
    std::string line;
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        PovTraceHit hit;
        if (!(fields >> hit.point.x >> hit.point.y >> hit.point.z >> hit.normal.x >> hit.normal.y >>
              hit.normal.z)) {
            work.keep();
            throw Error((work.path() / "hits.txt").string() + ": line " + std::to_string(hits.size() + 1) +
                        " is not six numbers");
        }
        hit.hit = hit.normal != DVec3(0.0);  // a hit always has a unit normal
        hits.push_back(hit);
    }
    if (hits.size() != rays.size()) {
        work.keep();
        throw Error((work.path() / "hits.txt").string() + ": POV-Ray traced " + std::to_string(hits.size()) +
                    " of " + std::to_string(rays.size()) + " rays");
    }
    return hits;
}

HitSetComparison compareWithOracle(const Scene& scene, const std::vector<OracleRay>& rays,
                                   const std::vector<PovTraceHit>& povHits) {
    if (rays.size() != povHits.size()) throw Error("hit-set comparison: ray and hit counts differ");
    constexpr size_t kMaxMismatchLines = 5;
    Oracle oracle(scene);
    HitSetComparison result;
    result.rays = rays.size();
    result.pointTolerance = kHitSetPointTolerance * sceneSize(scene);
    std::vector<double> pointErrors;

    for (size_t r = 0; r < rays.size(); ++r) {
        // The oracle's closest hit (lowest id on ties), and whether the ray passes within
        // kHitSetEdgeMargin of an edge, inside or outside, no farther than that hit.
        OracleHit best;
        double nearEdgeT = std::numeric_limits<double>::infinity();
        for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim) {
            std::optional<OracleHit> hit = oracle.intersect(prim, rays[r], kHitSetEdgeMargin);
            if (!hit) continue;
            if (hit->edgeMargin < kHitSetEdgeMargin) nearEdgeT = std::min(nearEdgeT, hit->t);
            if (hit->edgeMargin >= 0.0 && hit->t < best.t) best = *hit;
        }
        if (std::isfinite(nearEdgeT) && nearEdgeT <= best.t) {
            ++result.nearEdge;
            continue;
        }
        ++result.compared;
        const PovTraceHit& pov = povHits[r];
        std::ostringstream where;
        where.precision(17);
        where << "ray " << r << " (" << rays[r].origin.x << " " << rays[r].origin.y << " " << rays[r].origin.z
              << " -> " << rays[r].direction.x << " " << rays[r].direction.y << " " << rays[r].direction.z << "): ";
        if (pov.hit != best.hit) {
            if (result.mismatches.size() < kMaxMismatchLines)
                result.mismatches.push_back(where.str() + (best.hit ? "oracle hits primitive " +
                                                                          std::to_string(best.prim) + ", POV-Ray misses"
                                                                    : "POV-Ray hits, the oracle misses"));
            continue;
        }
        ++result.hitMissAgreements;
        if (!best.hit) continue;
        ++result.bothHit;
        double error = glm::length(pov.point - best.point);
        pointErrors.push_back(error);
        result.maxPointError = std::max(result.maxPointError, error);
        result.maxNormalError =
            std::max(result.maxNormalError, 1.0 - std::abs(glm::dot(glm::normalize(pov.normal), best.normal)));
        if (!(error <= result.pointTolerance)) {
            ++result.pointsOverTolerance;
            if (result.mismatches.size() < kMaxMismatchLines) {
                std::ostringstream text;
                text.precision(3);
                text << "hit points differ by " << error << " (tolerance " << result.pointTolerance << ")";
                result.mismatches.push_back(where.str() + text.str());
            }
        }
    }
    if (!pointErrors.empty()) {
        auto middle = pointErrors.begin() + static_cast<std::ptrdiff_t>(pointErrors.size() / 2);
        std::nth_element(pointErrors.begin(), middle, pointErrors.end());
        result.medianPointError = *middle;
    }
    return result;
}

}  // namespace rtlab
