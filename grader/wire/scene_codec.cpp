#include "grader/wire/scene_codec.h"

namespace rtlab::grader {
namespace {

constexpr uint64_t kMaxElements = uint64_t(1) << 26;  // far above any graded scene
constexpr uint64_t kMaxName = 1024;

}  // namespace

void writeScene(const Scene& scene, ByteWriter& out) {
    const Triangles& t = scene.triangles;
    out.putVector(t.positions);
    out.putVector(t.normals);
    out.putVector(t.indices);
    out.putVector(t.material);
    out.putVector(t.smooth);
    out.putVector(scene.spheres);
    out.put<uint64_t>(scene.materials.size());
    for (const Material& m : scene.materials) {
        out.putString(m.name);
        out.put(m.albedo);
        out.put(m.emission);
        out.put<uint8_t>(m.doubleSided);
    }
    out.put<uint64_t>(scene.lights.size());
    for (const PointLight& l : scene.lights) {
        out.putString(l.name);
        out.put(l.position);
        out.put(l.intensity);
    }
    out.put<uint64_t>(scene.cameras.size());
    for (const Camera& c : scene.cameras) {
        out.putString(c.name);
        out.put(c.position);
        out.put(c.forward);
        out.put(c.up);
        out.put(c.yfov);
        out.put(c.aspectRatio);
    }
}

Scene readScene(ByteReader& in) {
    Scene scene;
    Triangles& t = scene.triangles;
    t.positions = in.getVector<Vec3>(kMaxElements);
    t.normals = in.getVector<Vec3>(kMaxElements);
    t.indices = in.getVector<std::array<uint32_t, 3>>(kMaxElements);
    t.material = in.getVector<uint32_t>(kMaxElements);
    t.smooth = in.getVector<uint8_t>(kMaxElements);
    scene.spheres = in.getVector<Sphere>(kMaxElements);
    auto count = [&in] {
        auto n = in.get<uint64_t>();
        if (n > kMaxElements) throw WireError("a scene list is too long");
        return n;
    };
    for (uint64_t i = count(); i > 0; --i) {
        Material& m = scene.materials.emplace_back();
        m.name = in.getString(kMaxName);
        m.albedo = in.get<Vec3>();
        m.emission = in.get<Vec3>();
        m.doubleSided = in.get<uint8_t>() != 0;
    }
    for (uint64_t i = count(); i > 0; --i) {
        PointLight& l = scene.lights.emplace_back();
        l.name = in.getString(kMaxName);
        l.position = in.get<Vec3>();
        l.intensity = in.get<Vec3>();
    }
    for (uint64_t i = count(); i > 0; --i) {
        Camera& c = scene.cameras.emplace_back();
        c.name = in.getString(kMaxName);
        c.position = in.get<DVec3>();
        c.forward = in.get<DVec3>();
        c.up = in.get<DVec3>();
        c.yfov = in.get<double>();
        c.aspectRatio = in.get<double>();
    }
    for (const auto& tri : t.indices)
        for (uint32_t v : tri)
            if (v >= t.positions.size() || (!t.normals.empty() && v >= t.normals.size())) throw WireError("a triangle index is out of range");
    if (t.material.size() != t.indices.size() || t.smooth.size() != t.indices.size()) throw WireError("per-triangle lists differ in length");
    return scene;
}

}  // namespace rtlab::grader
