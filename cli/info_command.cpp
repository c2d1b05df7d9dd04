// rtlab info SCENE [--camera NAME]: what the loader made of a scene — primitives, bounds,
// materials, lights, cameras and the glTF features it met.
#include "cli/commands.h"
#include "framework/scene/gltf_loader.h"

#include <cmath>
#include <iostream>
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
        out << "\n";
    }

    out << "lights     " << scene.lights.size() << "\n";
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& l = scene.lights[i];
        out << "  " << i << " " << quoted(l.name) << "  point at " << format(l.position) << "  intensity "
            << format(l.intensity) << " W/sr\n";
    }

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
