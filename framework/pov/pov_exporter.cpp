#include "framework/pov/pov_exporter.h"

#include "framework/core/error.h"
#include "framework/pov/pov_format.h"
#include "framework/pov/pov_reference.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <unordered_map>

namespace rtlab {
namespace {

using pov::number;
using pov::vector;
using pov::vector32;

std::string textureName(uint32_t material) { return "RtlabMaterial" + std::to_string(material); }

void writeCamera(std::ostream& out, const Camera& camera) {
    DVec3 lookAt = camera.position + glm::normalize(camera.forward);
    out << "// POV-Ray's angle is the horizontal field of view: 2 atan(aspect tan(yfov/2)), which\n"
           "// gives |direction| = 0.5 / tan(yfov/2), the length our camera uses.\n"
        << "camera { perspective\n"
        << "  location " << vector(camera.position) << "\n"
        << "  right -x*image_width/image_height  up y  // negative right: right-handed data\n"
        << "  angle degrees(2*atan(image_width/image_height*tan(" << number(camera.yfov) << "/2)))\n"
        << "  sky " << vector(camera.up) << "\n"
        << "  look_at " << vector(lookAt) << "\n}\n\n";
}

void writeLights(std::ostream& out, const Scene& scene) {
    double fd = kPovFadeDistance;
    for (const PointLight& light : scene.lights) {
        // colour / (2 FD^2) * 2 / (1 + d^2/FD^2) = colour / (d^2 + FD^2); colour = I / pi.
        DVec3 colour = DVec3(light.intensity) / std::numbers::pi / (2.0 * fd * fd);
        out << "light_source { " << vector(DVec3(light.position)) << " color rgb " << vector(colour)
            << " fade_distance " << number(fd) << " fade_power 2 }";
        if (!light.name.empty()) out << "  // " << light.name;
        out << "\n";
    }
    out << "\n";
}

// Diffuse with pigment = albedo. Emission in POV-Ray is scaled by the pigment, which fails for
// a black albedo channel, so an emissive material averages two layers (weights 1:1), each
// doubled: a diffuse one with pigment 2 albedo and an emitting one with pigment 2 emission.
void writeMaterials(std::ostream& out, const Scene& scene) {
    static constexpr const char* kDiffuse =
        "finish { ambient 0 emission 0 diffuse 1 brilliance 1 specular 0 phong 0 }";
    static constexpr const char* kEmitting =
        "finish { ambient 0 emission 1 diffuse 0 brilliance 1 specular 0 phong 0 }";
    for (uint32_t m = 0; m < scene.materials.size(); ++m) {
        const Material& material = scene.materials[m];
        out << "#declare " << textureName(m) << " = texture {";
        if (material.emission == Vec3(0.0f)) {
            out << " pigment { color rgb " << vector32(material.albedo) << " } " << kDiffuse << " }";
        } else {
            out << " average texture_map {\n"
                << "  [1 pigment { color rgb " << vector(2.0 * DVec3(material.albedo)) << " } " << kDiffuse
                << " ]\n"
                << "  [1 pigment { color rgb " << vector(2.0 * DVec3(material.emission)) << " } "
                << kEmitting << " ] } }";
        }
        if (!material.name.empty()) out << "  // " << material.name;
        out << "\n";
    }
    out << "\n";
}

// One mesh2 for the triangles with (or without) smooth normals, with only the vertices they
// use, a texture_list of the scene's materials and a texture index per face.
void writeMesh2(std::ostream& out, const Scene& scene, bool smooth) {
    const Triangles& triangles = scene.triangles;
    std::vector<uint32_t> faces;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t)
        if ((triangles.smooth[t] != 0) == smooth) faces.push_back(t);
    if (faces.empty()) return;

    std::unordered_map<uint32_t, uint32_t> localIndex;
    std::vector<uint32_t> vertices;
    for (uint32_t t : faces)
        for (uint32_t v : triangles.indices[t])
            if (localIndex.emplace(v, static_cast<uint32_t>(vertices.size())).second) vertices.push_back(v);

    out << "mesh2 {  // " << faces.size() << (smooth ? " smooth" : " flat") << " triangles\n";
    out << "  vertex_vectors { " << vertices.size();
    for (uint32_t v : vertices) out << ",\n    " << vector32(triangles.positions[v]);
    out << " }\n";
    if (smooth) {
        // As many normals as vertices: POV-Ray reuses face_indices for them.
        out << "  normal_vectors { " << vertices.size();
        for (uint32_t v : vertices) out << ",\n    " << vector32(triangles.normals[v]);
        out << " }\n";
    }
    out << "  texture_list { " << scene.materials.size();
    for (uint32_t m = 0; m < scene.materials.size(); ++m) out << ", texture { " << textureName(m) << " }";
    out << " }\n";
    out << "  face_indices { " << faces.size();
    for (uint32_t t : faces) {
        const auto& idx = triangles.indices[t];
        out << ",\n    <" << localIndex[idx[0]] << "," << localIndex[idx[1]] << "," << localIndex[idx[2]]
            << ">, " << triangles.material[t];
    }
    out << " }\n}\n\n";
}

void writeSpheres(std::ostream& out, const Scene& scene) {
    for (const Sphere& s : scene.spheres)
        out << "sphere { " << vector(DVec3(s.centre)) << ", " << number(s.radius) << " texture { "
            << textureName(s.material) << " } }\n";
    if (!scene.spheres.empty()) out << "\n";
}

void checkExportable(const Scene& scene) {
    if (scene.triangles.normals.size() != scene.triangles.positions.size())
        for (uint32_t t = 0; t < scene.triangleCount(); ++t)
            if (scene.triangles.smooth[t])
                throw Error(scene.sourcePath + ": triangle " + std::to_string(t) +
                            " is smooth but the mesh has no normal per vertex (cannot export to POV-Ray)");
    auto materialCount = static_cast<uint32_t>(scene.materials.size());
    for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim)
        if (scene.materialOf(prim) >= materialCount)
            throw Error(scene.sourcePath + ": primitive " + std::to_string(prim) +
                        " names material " + std::to_string(scene.materialOf(prim)) + " of " +
                        std::to_string(materialCount) + " (cannot export to POV-Ray)");
    if (scene.triangleCount() > 0 && materialCount == 0)
        throw Error(scene.sourcePath + ": triangles but no materials (cannot export to POV-Ray)");
}

}  // namespace

std::string exportPovScene(const Scene& scene, const Camera& camera, int width, int height) {
    checkExportable(scene);
    std::ostringstream out;
    out << "// " << (scene.sourcePath.empty() ? std::string("scene") : scene.sourcePath) << ", camera '"
        << camera.name << "', exported by " << kPovExporterVersion << ".\n"
        << "// Render: povray -iTHIS.pov " << povReferenceSettings(width, height) << " -OOUT.png\n"
        << "// Values are linear radiance [W/(sr m^2)], as rtlab's renderer writes them.\n"
        << "#version 3.7;\n"
        << "global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 1 }\n\n";
    writeCamera(out, camera);
    writeLights(out, scene);
    writeMaterials(out, scene);
    writeMesh2(out, scene, false);
    writeMesh2(out, scene, true);
    writeSpheres(out, scene);
    return out.str();
}

std::string exportPovTraceObject(const Scene& scene, std::string_view name) {
    if (scene.primitiveCount() == 0) throw Error(scene.sourcePath + ": no primitives to trace");
    std::ostringstream out;
    out << "#declare " << name << " = union {\n";
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        auto v = scene.triangleVertices(t);
        out << "  triangle { " << vector(DVec3(v[0])) << ", " << vector(DVec3(v[1])) << ", "
            << vector(DVec3(v[2])) << " }\n";
    }
    for (const Sphere& s : scene.spheres)
        out << "  sphere { " << vector(DVec3(s.centre)) << ", " << number(s.radius) << " }\n";
    out << "}\n";
    return out.str();
}

}  // namespace rtlab
