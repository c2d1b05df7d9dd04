#include "bench/report.h"

#include "framework/core/error.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>

namespace rtlab::bench {

namespace {

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// Throughputs: two decimals, more for the very slow rows (brute force).
std::string mrays(double v) { return fixed(v, v < 0.1 ? 4 : 2); }

// Build times: a few significant digits whatever the size.
std::string milliseconds(double ms) { return fixed(ms, ms < 10 ? 2 : ms < 100 ? 1 : 0); }

const ThroughputRecord* find(const std::vector<ThroughputRecord>& records, const std::string& scene,
                             const std::string& system, RayKind rays, int threads) {
    for (const ThroughputRecord& r : records)
        if (r.scene == scene && r.system == system && r.rays == rays && r.threads == threads) return &r;
    return nullptr;
}

std::vector<std::string> scenesInOrder(const std::vector<ThroughputRecord>& records) {
    std::vector<std::string> scenes;
    for (const ThroughputRecord& r : records)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    return scenes;
}

std::vector<std::string> systemsInOrder(const std::vector<ThroughputRecord>& records, const std::string& scene) {
    std::vector<std::string> systems;
    for (const ThroughputRecord& r : records)
        if (r.scene == scene && std::find(systems.begin(), systems.end(), r.system) == systems.end())
            systems.push_back(r.system);
    return systems;
}

// A CSV field in double quotes (notes may hold commas).
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

template <typename T, typename F>
std::string optionalText(const std::optional<T>& value, F format) {
    return value ? format(*value) : "–";
}

}  // namespace

void writeMarkdown(std::ostream& out, const std::vector<ThroughputRecord>& records) {
    for (const std::string& scene : scenesInOrder(records)) {
        const ThroughputRecord& first = *std::find_if(records.begin(), records.end(),
                                                      [&](const ThroughputRecord& r) { return r.scene == scene; });
        out << "\n### " << scene << " (" << first.triangles << " triangles; load average " << first.loadAverage
            << " at the start)\n\n";
        out << "| system | build ms 1T | build ms 2T | primary 1T | incoherent 1T | primary 2T | incoherent 2T "
               "| × Embree MEDIUM prim/inc 1T | SAH cost | node visits/ray prim/inc | cells or planes/ray prim/inc "
               "| prim tests/ray prim/inc | bytes/tri | refs/tri | mismatches prim/inc |\n";
        out << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
        for (const std::string& system : systemsInOrder(records, scene)) {
            const ThroughputRecord* p1 = find(records, scene, system, RayKind::Primary, 1);
            const ThroughputRecord* i1 = find(records, scene, system, RayKind::Incoherent, 1);
            const ThroughputRecord* p2 = find(records, scene, system, RayKind::Primary, 2);
            const ThroughputRecord* i2 = find(records, scene, system, RayKind::Incoherent, 2);
            if (!p1 || !i1 || !p2 || !i2) continue;
            if (!p1->measured) {
                out << "| " << system << " | " << p1->note << " |||||||||||||\n";
                continue;
            }
            auto perRay = [](const ThroughputRecord* a, const ThroughputRecord* b, auto member) {
                return optionalText(a->*member, [](double v) { return fixed(v, 1); }) + " / " +
                       optionalText(b->*member, [](double v) { return fixed(v, 1); });
            };
            bool singleThreadedBuild = !p2->parallelBuild;
            out << "| " << system << (p1->note.empty() ? "" : " (" + p1->note + ")") << " | " << milliseconds(p1->buildMs) << " | "
                << (singleThreadedBuild ? "(1T)" : milliseconds(p2->buildMs)) << " | "
                << mrays(p1->mraysPerSecond) << " | " << mrays(i1->mraysPerSecond) << " | "
                << mrays(p2->mraysPerSecond) << " | " << mrays(i2->mraysPerSecond) << " | "
                << mrays(p1->ratioToEmbreeMedium) << " / " << mrays(i1->ratioToEmbreeMedium) << " | "
                << optionalText(p1->sahCost, [](double v) { return fixed(v, 1); }) << " | "
                << perRay(p1, i1, &ThroughputRecord::nodeVisitsPerRay) << " | "
                << perRay(p1, i1, p1->cellStepsPerRay ? &ThroughputRecord::cellStepsPerRay : &ThroughputRecord::planeStepsPerRay) << " | "
                << perRay(p1, i1, &ThroughputRecord::primitiveTestsPerRay) << " | "
                << fixed(p1->bytesPerTriangle, 1) << " | "
                << optionalText(p1->referencesPerTriangle, [](double v) { return fixed(v, 2); }) << " | "
                << optionalText(p1->mismatches, [](uint64_t v) { return std::to_string(v); }) << " / "
                << optionalText(i1->mismatches, [](uint64_t v) { return std::to_string(v); }) << " |\n";
        }
    }
    out << "\nMrays/s: best pass, closest hit, one query per ray; 2T = total of two threads. rtlab's "
           "builders are single-threaded (all but fastbvh), and their 2T build column shows (1T). Embree does not "
           "count work in its release build (–); the wide BVHs (bvh4, bvh8) count a wide node as one visit. "
           "Bytes per triangle: the built structure only (rtlab: the BVH's 32-byte nodes, the octree's 12-byte nodes, the KD-tree's 8-byte nodes, the grids' "
           "4-byte cell offsets, + 4-byte indices; bvh4/bvh8/fastbvh: "
           "128/256-byte nodes and the triangles in leaf order, four to a 160-byte packet; Embree: what "
           "its memory monitor saw rtcCommitScene keep). "
           "References per triangle: the primitive ids the structure lists, per triangle (a triangle in "
           "several grid cells, octree leaves or KD-tree leaves counts in each). "
           "Mismatches: rays whose hit/miss or t (|Δt| > 1e-4·max(1,t)) differ from Embree MEDIUM, 1T.\n";
}

void writeCsv(const std::string& path, const std::vector<ThroughputRecord>& records) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot open for writing");
    out << "scene,triangles,system,rays,threads,build_ms,mrays_per_s,ratio_to_embree_medium,sah_cost,"
           "node_visits_per_ray,prim_tests_per_ray,bytes_per_triangle,mismatches,hits,sum_t,load_average,note,"
           "cell_steps_per_ray,plane_steps_per_ray,references_per_triangle\n";
    auto number = [](const std::optional<double>& v) { return v ? fixed(*v, 4) : std::string(); };
    for (const ThroughputRecord& r : records) {
        bool measured = r.measured;
        out << r.scene << ',' << r.triangles << ',' << r.system << ',' << rayKindName(r.rays) << ',' << r.threads << ','
            << (measured ? fixed(r.buildMs, 3) : "") << ',' << (measured ? fixed(r.mraysPerSecond, 4) : "") << ','
            << (measured ? fixed(r.ratioToEmbreeMedium, 4) : "") << ',' << number(r.sahCost) << ','
            << number(r.nodeVisitsPerRay) << ',' << number(r.primitiveTestsPerRay) << ','
            << (measured ? fixed(r.bytesPerTriangle, 2) : "") << ','
            << (r.mismatches ? std::to_string(*r.mismatches) : "") << ',' << (measured ? std::to_string(r.hits) : "")
            << ',' << (measured ? fixed(r.sumT, 3) : "") << ',' << r.loadAverage << ',' << quoted(r.note) << ','
            << number(r.cellStepsPerRay) << ',' << number(r.planeStepsPerRay) << ',' << number(r.referencesPerTriangle) << '\n';
    }
    if (!out.flush()) throw Error(path + ": write failed");
}

void writeTargets(std::ostream& out, const std::vector<ThroughputRecord>& records) {
    // The fastest rtlab BVH of a scene on one ray set, single thread.
    auto best = [&records](const std::string& scene, RayKind rays) {
        const ThroughputRecord* fastest = nullptr;
        for (const ThroughputRecord& r : records)
            if (r.scene == scene && r.rays == rays && r.threads == 1 && r.measured && r.system.starts_with("rtlab:bvh") &&
                (!fastest || r.mraysPerSecond > fastest->mraysPerSecond))
                fastest = &r;
        return fastest;
    };
    out << "\n### Targets (issue 6): best rtlab BVH against Embree MEDIUM, single thread\n\n"
        << "| scene | best primary (system) | ratio | target ≥ 0.7 | best incoherent (system) | ratio | target ≥ 0.4 |\n"
        << "|---|---|--:|:-:|---|--:|:-:|\n";
    for (const std::string& scene : scenesInOrder(records)) {
        const ThroughputRecord* primary = best(scene, RayKind::Primary);
        const ThroughputRecord* incoherent = best(scene, RayKind::Incoherent);
        if (!primary || !incoherent) continue;
        out << "| " << scene << " | " << fixed(primary->mraysPerSecond, 2) << " (" << primary->system << ") | "
            << fixed(primary->ratioToEmbreeMedium, 2) << " | " << (primary->ratioToEmbreeMedium >= 0.7 ? "met" : "**not met**")
            << " | " << fixed(incoherent->mraysPerSecond, 2) << " (" << incoherent->system << ") | "
            << fixed(incoherent->ratioToEmbreeMedium, 2) << " | "
            << (incoherent->ratioToEmbreeMedium >= 0.4 ? "met" : "**not met**") << " |\n";
    }
    // The build target is about the BVHs that trace fastest (a wide BVH's build includes folding
    // the binary tree), next to the default bvh-buckets:12.
    const ThroughputRecord* embree = find(records, "sphereflake", "embree:medium", RayKind::Primary, 1);
    if (!embree || !embree->measured) return;
    std::vector<std::string> systems{"rtlab:bvh-buckets:12"};
    for (RayKind rays : {RayKind::Primary, RayKind::Incoherent})
        if (const ThroughputRecord* r = best("sphereflake", rays);
            r && std::find(systems.begin(), systems.end(), r->system) == systems.end())
            systems.push_back(r->system);
    for (const std::string& system : systems) {
        const ThroughputRecord* r = find(records, "sphereflake", system, RayKind::Primary, 1);
        if (!r || !r->measured) continue;
        double ratio = r->buildMs / embree->buildMs;
        out << "\nSphereflake single-thread build, " << r->system << ": " << milliseconds(r->buildMs) << " ms = "
            << fixed(ratio, 2) << "× Embree MEDIUM (" << milliseconds(embree->buildMs)
            << " ms); target ≤ 1.5×: " << (ratio <= 1.5 ? "met" : "**not met**") << ".\n";
    }
}

const ThroughputRecord* primaryRow(const std::vector<ThroughputRecord>& records, const std::string& scene, const std::string& system) {
    for (const ThroughputRecord& r : records)
        if (r.scene == scene && r.system == system && r.rays == RayKind::Primary && r.threads == 1 && r.measured) return &r;
    return nullptr;
}

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

std::string verdict(bool met) { return met ? "met" : "**not met**"; }

}  // namespace rtlab::bench
