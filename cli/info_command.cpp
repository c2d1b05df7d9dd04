// rtlab info SCENE [--camera NAME]: what the loader made of a scene — primitives, bounds,
// materials, point lights, emitters (area and sphere lights), cameras and the glTF features it met.
#include "cli/commands.h"
#include "framework/scene/emitters.h"
#include "framework/scene/gltf_loader.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>

namespace rtlab::cli {
namespace {

struct InfoOptions {
    std::string scenePath;
    std::string cameraName;
};

template <typename V>
std::string format(const V& v) {
    std::ostringstream out;
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

std::string quoted(const std::string& name) { return name.empty() ? "(unnamed)" : "'" + name + "'"; }

// The emitters of one material.
struct EmitterGroup {
    size_t triangles = 0, spheres = 0;
    double area = 0.0;   // m^2
    double power = 0.0;  // W
};

void printInfo(const InfoOptions& options) {
    Scene scene = loadGltf(options.scenePath);
    const Camera* selected = scene.cameras.empty() ? nullptr : &scene.camera(options.cameraName);
    std::ostream& out = std::cout;

    size_t smooth = 0;
    for (uint8_t s : scene.triangles.smooth) smooth += s;
    out << "scene      " << scene.sourcePath << "\n";
    out << "primitives " << scene.primitiveCount() << ": " << scene.triangleCount() << " triangles ("
        << scene.triangles.positions.size() << " vertices, " << smooth << " with vertex normals), "
        << scene.spheres.size() << " spheres\n";
    Bounds3f bounds = scene.bounds();
    if (bounds.isEmpty())
        out << "bounds     empty\n";
    else
        out << "bounds     " << format(bounds.lower) << " - " << format(bounds.upper) << "\n";

    out << "materials  " << scene.materials.size() << "\n";
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        out << "  " << i << " " << quoted(m.name) << "  albedo " << format(m.albedo);
        if (m.emission != Vec3(0.0f)) out << "  emission " << format(m.emission) << " W/(sr m^2)";
        if (m.doubleSided) out << "  double-sided";
        out << "\n";
    }

    out << "lights     " << scene.lights.size() << "\n";
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& l = scene.lights[i];
        out << "  " << i << " " << quoted(l.name) << "  point at " << format(l.position) << "  intensity "
            << format(l.intensity) << " W/sr\n";
    }

    // Emissive triangles and spheres (framework/scene/emitters.h), summed per material.
    std::vector<Emitter> emitters = findEmitters(scene);
    std::map<uint32_t, EmitterGroup> groups;
    for (const Emitter& e : emitters) {
        EmitterGroup& group = groups[scene.materialOf(e.prim)];
        ++(scene.isSphere(e.prim) ? group.spheres : group.triangles);
        group.area += e.area;
        group.power += e.power;
    }
    out << "emitters   " << emitters.size() << "\n";
    for (const auto& [material, group] : groups)
        out << "  material " << material << " " << quoted(scene.materials[material].name) << "  " << group.triangles
            << " triangles, " << group.spheres << " spheres  area " << group.area << " m^2  power " << group.power << " W\n";

    out << "cameras    " << scene.cameras.size() << "\n";
    for (size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& c = scene.cameras[i];
        out << "  " << i << " " << quoted(c.name) << "  position " << format(c.position) << "  forward "
            << format(c.forward) << "  up " << format(c.up) << "  yfov " << c.yfov * 180.0 / std::numbers::pi
            << " deg";
        if (c.aspectRatio > 0.0) out << "  aspect " << c.aspectRatio;
        if (&c == selected) out << "  [selected]";
        out << "\n";
    }

    out << "features   ";
    if (scene.featuresUsed.empty()) out << "none beyond core glTF 2.0";
    for (size_t i = 0; i < scene.featuresUsed.size(); ++i) out << (i ? ", " : "") << scene.featuresUsed[i];
    out << "\n";
}

}  // namespace

void addInfoCommand(CLI::App& app) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* info = app.add_subcommand(
        "info", "Show what a glTF scene contains: primitives, bounds, materials, lights, cameras, features");
    info->add_option("scene", options->scenePath, "glTF 2.0 scene (.gltf or .glb)")->required();
    info->add_option("--camera", options->cameraName, "Camera to mark as selected (default: the first)");
    info->callback([options] { printInfo(*options); });
}

}  // namespace rtlab::cli
