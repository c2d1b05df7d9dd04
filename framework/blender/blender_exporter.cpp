#include "framework/blender/blender_exporter.h"

#include "framework/blender/emitter_tessellation.h"
#include "framework/core/error.h"
#include "framework/core/shortest_decimal.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <sstream>
#include <unordered_map>

namespace rtlab {
namespace {

constexpr const char* kWhat = "Blender export";

std::string number(double value) { return shortestDecimal(value, kWhat); }

// glTF's +Y up to Blender's +Z up, a rotation (x, y, z) -> (x, -z, y): exact in float.
DVec3 zUp(const DVec3& p) { return {p.x, -p.z, p.y}; }
Vec3 zUp(const Vec3& p) { return {p.x, -p.z, p.y}; }

// A Python tuple, appended piece by piece ("(" + std::string trips GCC 12's -Wrestrict false
// positive).
std::string pythonTuple(std::initializer_list<std::string> items) {
    std::string text(1, '(');
    for (const std::string& item : items) text.append(text.size() > 1 ? ", " : "").append(item);
    return text.append(1, ')');
}

std::string tuple(const DVec3& v) { return pythonTuple({number(v.x), number(v.y), number(v.z)}); }
std::string tuple32(const Vec3& v) {
    return pythonTuple({shortestDecimal32(v.x, kWhat), shortestDecimal32(v.y, kWhat), shortestDecimal32(v.z, kWhat)});
}

// A Python string literal: JSON's escapes (ASCII only) are Python's, so a name from the scene
// file can never end the string or the line.
std::string pythonString(const std::string& text) {
    return nlohmann::json(text).dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
}

// The functions the generated part calls; everything scene-specific comes after them.
constexpr const char* kPrelude = R"PY(import os
import sys

import bpy
from mathutils import Matrix


def material(name, albedo, radiance=None, double_sided=False):
    """Lambert (Diffuse BSDF, roughness 0: albedo / pi); an emitter adds an Emission shader of
    strength x colour = radiance, front face only unless double_sided: Cycles' emission is
    two-sided, rtlab's triangles emit from the front (counter-clockwise) face."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*albedo, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    surface = diffuse.outputs["BSDF"]
    if radiance is not None:
        strength = max(radiance)
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (*[c / strength for c in radiance], 1.0)
        emission.inputs["Strength"].default_value = strength
        emitted = emission.outputs["Emission"]
        if not double_sided:
            # Seen from the back the mix takes its empty second shader: no emission.
            geometry = nodes.new("ShaderNodeNewGeometry")
            front_only = nodes.new("ShaderNodeMixShader")
            links.new(geometry.outputs["Backfacing"], front_only.inputs["Fac"])
            links.new(emitted, front_only.inputs[1])
            emitted = front_only.outputs["Shader"]
        both = nodes.new("ShaderNodeAddShader")
        links.new(surface, both.inputs[0])
        links.new(emitted, both.inputs[1])
        surface = both.outputs["Shader"]
    links.new(surface, nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    return m


def mesh(name, vertices, triangles, material_of, materials, normals=None):
    """One object; normals (one per vertex) make it smooth shaded with exactly those normals."""
    data = bpy.data.meshes.new(name)
    data.from_pydata(vertices, [], triangles)
    for m in materials:
        data.materials.append(m)
    data.polygons.foreach_set("material_index", material_of)
    if normals is not None:
        data.polygons.foreach_set("use_smooth", [True] * len(triangles))
        data.use_auto_smooth = True
        data.normals_split_custom_set_from_vertices(normals)
    data.update()
    bpy.context.scene.collection.objects.link(bpy.data.objects.new(name, data))


def sphere(name, centre, radius, m):
    """An exact sphere: Cycles renders a point of a point cloud as one (geometry nodes: one
    vertex, Mesh to Points)."""
    data = bpy.data.meshes.new(name)
    data.from_pydata([(0.0, 0.0, 0.0)], [], [])
    obj = bpy.data.objects.new(name, data)
    obj.location = centre
    tree = bpy.data.node_groups.new(name, "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    points = tree.nodes.new("GeometryNodeMeshToPoints")
    points.inputs["Radius"].default_value = radius
    shading = tree.nodes.new("GeometryNodeSetMaterial")
    shading.inputs["Material"].default_value = m
    tree.links.new(tree.nodes.new("NodeGroupInput").outputs[0], points.inputs["Mesh"])
    tree.links.new(points.outputs["Points"], shading.inputs["Geometry"])
    tree.links.new(shading.outputs["Geometry"], tree.nodes.new("NodeGroupOutput").inputs[0])
    obj.modifiers.new(name, "NODES").node_group = tree
    bpy.context.scene.collection.objects.link(obj)


def point_light(name, position, watts, colour):
    """Blender's point light of power P [W] has intensity P / (4 pi) W/sr; radius 0 (the
    default 0.25 m would make it a disk)."""
    data = bpy.data.lights.new(name, "POINT")
    data.energy = watts
    data.color = colour
    data.shadow_soft_size = 0.0
    obj = bpy.data.objects.new(name, data)
    obj.location = position
    bpy.context.scene.collection.objects.link(obj)


def camera(position, right, up, back, yfov, clip_end):
    """Blender's camera looks down its local -Z with +Y up and +X right."""
    data = bpy.data.cameras.new("camera")
    data.type = "PERSP"
    data.sensor_fit = "VERTICAL"
    data.angle_y = yfov
    data.clip_start = 1e-6
    data.clip_end = clip_end
    obj = bpy.data.objects.new("camera", data)
    obj.matrix_world = Matrix((  # rows: the columns are the camera's axes and position
        (right[0], up[0], back[0], position[0]),
        (right[1], up[1], back[1], position[1]),
        (right[2], up[2], back[2], position[2]),
        (0.0, 0.0, 0.0, 1.0),
    ))
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj


def exact_settings(scene, width, height, samples, seed):
    """Direct light only, every sample at the pixel centre, no Russian roulette on light
    samples, no denoising or adaptive sampling, a fixed seed, linear 32-bit EXR."""
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = samples
    cycles.seed = seed
    cycles.use_animated_seed = False
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.light_sampling_threshold = 0.0
    cycles.max_bounces = 0
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.filter_width = 0.01
    render = scene.render
    render.resolution_x, render.resolution_y = width, height
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.film_transparent = False
    render.dither_intensity = 0.0
    render.use_compositing = False
    render.use_sequencer = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    image = render.image_settings
    image.file_format = "OPEN_EXR"
    image.color_depth = "32"
    image.color_mode = "RGB"
    image.exr_codec = "ZIP"


def output_path():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(arguments) != 1:
        sys.exit("usage: blender -b --factory-startup --python-exit-code 1 -P SCRIPT -- OUT.exr")
    return os.path.abspath(arguments[0])


OUTPUT = output_path()
for leftover in list(bpy.data.objects):
    bpy.data.objects.remove(leftover, do_unlink=True)
)PY";

// Triangles as Blender mesh data: the vertices they use, emissive triangles cut
// (emitter_tessellation.h), zero-area triangles left out (they are never hit and emit nothing).
struct MeshPart {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<uint32_t> material;
};

bool zeroArea(const std::array<Vec3, 3>& v) {
    DVec3 n = glm::cross(DVec3(v[1]) - DVec3(v[0]), DVec3(v[2]) - DVec3(v[0]));
    return !(glm::dot(n, n) > 0.0);
}

MeshPart meshPart(const Scene& scene, bool smooth, double emitterEdge) {
    const Triangles& triangles = scene.triangles;
    MeshPart part;
    std::unordered_map<uint32_t, uint32_t> localIndex;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        if ((triangles.smooth[t] != 0) != smooth) continue;
        std::array<Vec3, 3> v = scene.triangleVertices(t);
        if (zeroArea(v)) continue;
        const auto& idx = triangles.indices[t];
        uint32_t material = triangles.material[t];
        int k = scene.materials[material].emission == Vec3(0.0f) ? 1 : cutsPerEdge(v, emitterEdge);
        if (k == 1) {
            std::array<uint32_t, 3> local{};
            for (int c = 0; c < 3; ++c) {
                auto [it, added] = localIndex.emplace(idx[c], static_cast<uint32_t>(part.positions.size()));
                if (added) {
                    part.positions.push_back(triangles.positions[idx[c]]);
                    if (smooth) part.normals.push_back(triangles.normals[idx[c]]);
                }
                local[c] = it->second;
            }
            part.triangles.push_back(local);
            part.material.push_back(material);
            continue;
        }
        std::vector<Vec3> normals;
        if (smooth) normals = {triangles.normals[idx[0]], triangles.normals[idx[1]], triangles.normals[idx[2]]};
        TriangleCut cut = cutTriangle(v, normals, k);
        auto base = static_cast<uint32_t>(part.positions.size());
        part.positions.insert(part.positions.end(), cut.positions.begin(), cut.positions.end());
        part.normals.insert(part.normals.end(), cut.normals.begin(), cut.normals.end());
        for (const auto& tri : cut.indices) {
            part.triangles.push_back({base + tri[0], base + tri[1], base + tri[2]});
            part.material.push_back(material);
        }
    }
    return part;
}

template <typename Item, typename Format>
void writeList(std::ostream& out, const std::vector<Item>& items, Format format) {
    out << "[";
    for (size_t i = 0; i < items.size(); ++i) out << (i ? ",\n    " : "\n    ") << format(items[i]);
    out << "]";
}

void writeMesh(std::ostream& out, const Scene& scene, bool smooth, double emitterEdge) {
    MeshPart part = meshPart(scene, smooth, emitterEdge);
    if (part.triangles.empty()) return;
    out << "mesh(" << (smooth ? "\"smooth triangles\"" : "\"flat triangles\"") << ",\n    ";
    writeList(out, part.positions, [](const Vec3& p) { return tuple32(zUp(p)); });
    out << ",\n    ";
    writeList(out, part.triangles, [](const std::array<uint32_t, 3>& t) {
        return pythonTuple({std::to_string(t[0]), std::to_string(t[1]), std::to_string(t[2])});
    });
    out << ",\n    ";
    writeList(out, part.material, [](uint32_t m) { return std::to_string(m); });
    out << ",\n    materials";
    if (smooth) {
        out << ",\n    normals=";
        writeList(out, part.normals, [](const Vec3& n) { return tuple32(zUp(n)); });
    }
    out << ")\n\n";
}

void writeMaterials(std::ostream& out, const Scene& scene) {
    out << "materials = [\n";
    for (const Material& m : scene.materials) {
        out << "    material(" << pythonString(m.name) << ", " << tuple(DVec3(m.albedo));
        if (m.emission != Vec3(0.0f)) {
            out << ", radiance=" << tuple(DVec3(m.emission));
            if (m.doubleSided) out << ", double_sided=True";
        }
        out << "),\n";
    }
    out << "]\n\n";
}

void writeSpheres(std::ostream& out, const Scene& scene) {
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        out << "sphere(\"sphere " << i << "\", " << tuple(zUp(DVec3(s.centre))) << ", " << number(s.radius)
            << ", materials[" << s.material << "])\n";
    }
    if (!scene.spheres.empty()) out << "\n";
}

void writeLights(std::ostream& out, const Scene& scene) {
    for (const PointLight& light : scene.lights) {
        double strongest = std::max({light.intensity.x, light.intensity.y, light.intensity.z});
        if (!(strongest > 0.0)) continue;  // a dark light adds nothing
        DVec3 colour = DVec3(light.intensity) / strongest;
        // I = P / (4 pi) W/sr in Blender: P = 4 pi I.
        out << "point_light(" << pythonString(light.name) << ", " << tuple(zUp(DVec3(light.position))) << ", "
            << number(4.0 * std::numbers::pi * strongest) << ", " << tuple(colour) << ")\n";
    }
    if (!scene.lights.empty()) out << "\n";
}

// The same frame as Camera::generateRayThrough: D along forward, R = normalize(D x up),
// U = normalize(R x D); Blender's local axes X = R, Y = U, Z = -D.
void writeCamera(std::ostream& out, const Scene& scene, const Camera& camera) {
    DVec3 d = glm::normalize(camera.forward);
    DVec3 r = glm::normalize(glm::cross(d, camera.up));
    DVec3 u = glm::normalize(glm::cross(r, d));
    // Far enough for the whole scene: no point of the box is farther than this.
    Bounds3f bounds = scene.bounds();
    double reach = 1.0;
    if (!bounds.isEmpty())
        reach += glm::length(DVec3(bounds.lower) - camera.position) + glm::length(DVec3(bounds.upper) - DVec3(bounds.lower));
    out << "camera(" << tuple(zUp(camera.position)) << ", " << tuple(zUp(r)) << ", " << tuple(zUp(u)) << ", "
        << tuple(zUp(-d)) << ", " << number(camera.yfov) << ", " << number(2.0 * reach) << ")\n";
}

void checkExportable(const Scene& scene, const BlenderSettings& settings) {
    const std::string& where = scene.sourcePath;
    if (settings.width < 1 || settings.height < 1 || settings.width > 65536 || settings.height > 65536)
        throw Error(where + ": image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                    " is out of range (cannot export to Blender)");
    if (settings.samples < 1 || settings.samples > (1 << 24) || settings.seed < 0)
        throw Error(where + ": samples " + std::to_string(settings.samples) + " or seed " +
                    std::to_string(settings.seed) + " out of range (cannot export to Blender)");
    if (!(settings.emitterEdge > 0.0) || !std::isfinite(settings.emitterEdge))
        throw Error(where + ": the longest emitter edge must be a positive length (cannot export to Blender)");
    if (scene.triangles.normals.size() != scene.triangles.positions.size())
        for (uint32_t t = 0; t < scene.triangleCount(); ++t)
            if (scene.triangles.smooth[t])
                throw Error(where + ": triangle " + std::to_string(t) +
                            " is smooth but the mesh has no normal per vertex (cannot export to Blender)");
    auto materialCount = static_cast<uint32_t>(scene.materials.size());
    for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim)
        if (scene.materialOf(prim) >= materialCount)
            throw Error(where + ": primitive " + std::to_string(prim) + " names material " +
                        std::to_string(scene.materialOf(prim)) + " of " + std::to_string(materialCount) +
                        " (cannot export to Blender)");
    if (std::string reason = blenderUnsupported(scene); !reason.empty())
        throw Error(where + ": " + reason + " (cannot export to Blender)");
}

}  // namespace

std::string blenderUnsupported(const Scene& scene) {
    for (const Sphere& s : scene.spheres)
        if (s.material < scene.materials.size() && scene.materials[s.material].emission != Vec3(0.0f))
            return "a sphere light: Blender 3.4 draws it as a disk facing the shading point, so sphere lights are "
                   "verified against closed forms (docs/verification.md#what-blender-does-not-verify)";
    return "";
}

std::string blenderSettingsText(const BlenderSettings& settings) {
    return "samples=" + std::to_string(settings.samples) + " seed=" + std::to_string(settings.seed) +
           " emitter-edge=" + number(settings.emitterEdge);
}

std::string exportBlenderScene(const Scene& scene, const Camera& camera, const BlenderSettings& settings) {
    checkExportable(scene, settings);
    std::ostringstream out;
    out << "# " << pythonString(scene.sourcePath.empty() ? std::string("scene") : scene.sourcePath) << ", camera "
        << pythonString(camera.name) << ", exported by " << kBlenderExporterVersion << " (" << blenderSettingsText(settings)
        << ").\n"
        << "# Render: blender -b --factory-startup --python-exit-code 1 -P THIS.py -- OUT.exr\n"
        << "# The EXR holds linear radiance [W/(sr m^2)], direct light only, as rtlab's renderer computes it.\n"
        << "# Coordinates: glTF +Y up is Blender +Z up, (x, y, z) -> (x, -z, y).\n"
        << kPrelude << "\n";
    writeMaterials(out, scene);
    writeMesh(out, scene, false, settings.emitterEdge);
    writeMesh(out, scene, true, settings.emitterEdge);
    writeSpheres(out, scene);
    writeLights(out, scene);
    writeCamera(out, scene, camera);
    out << "exact_settings(bpy.context.scene, " << settings.width << ", " << settings.height << ", " << settings.samples
        << ", " << settings.seed << ")\n"
        << "bpy.context.scene.render.filepath = OUTPUT\n"
        << "bpy.ops.render.render(write_still=True)\n"
        << "if not os.path.isfile(OUTPUT):\n"
        << "    sys.exit(\"Blender wrote no image to \" + OUTPUT)\n";
    return out.str();
}

}  // namespace rtlab
