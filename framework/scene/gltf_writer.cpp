#include "framework/scene/gltf_writer.h"

#include "framework/core/error.h"

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstring>

namespace rtlab {

namespace {

constexpr double kZNear = 1e-3;

class GltfBuilder {
public:
    explicit GltfBuilder(const Scene& scene) : scene_(scene) {
        model_.asset.version = "2.0";
        model_.asset.generator = "rtlab";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    tinygltf::Model build() {
        addMaterials();
        addTriangles();
        for (const Camera& camera : scene_.cameras) addCamera(camera);
        for (const PointLight& light : scene_.lights) addLight(light);
        for (const Sphere& sphere : scene_.spheres) addSphere(sphere);
        return std::move(model_);
    }

private:
    // Appends raw data as a bufferView (4-byte aligned) and returns an accessor over it.
    int addAccessor(const void* data, size_t bytes, int componentType, int type, size_t count, int target) {
        std::vector<unsigned char>& buffer = model_.buffers[0].data;
        buffer.resize((buffer.size() + 3) & ~size_t{3});
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        buffer.resize(buffer.size() + bytes);
        std::memcpy(buffer.data() + view.byteOffset, data, bytes);
        model_.bufferViews.push_back(view);

        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
        accessor.componentType = componentType;
        accessor.type = type;
        accessor.count = count;
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    int addNode(tinygltf::Node node) {
        model_.nodes.push_back(std::move(node));
        int index = static_cast<int>(model_.nodes.size()) - 1;
        model_.scenes[0].nodes.push_back(index);
        return index;
    }

    void addMaterials() {
        for (const Material& source : scene_.materials) {
            tinygltf::Material material;
            material.name = source.name;
            material.pbrMetallicRoughness.baseColorFactor = {source.albedo.x, source.albedo.y,
                                                             source.albedo.z, 1.0};
            material.pbrMetallicRoughness.metallicFactor = 0.0;
            material.pbrMetallicRoughness.roughnessFactor = 1.0;
            // emissiveFactor is clamped to [0, 1]; brighter emission needs the strength extension.
            float strength = std::max({source.emission.x, source.emission.y, source.emission.z});
            if (strength > 0.0f) {
                Vec3 factor = strength > 1.0f ? source.emission / strength : source.emission;
                material.emissiveFactor = {factor.x, factor.y, factor.z};
                if (strength > 1.0f) {
                    tinygltf::Value::Object extension{{"emissiveStrength", tinygltf::Value(double(strength))}};
                    material.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(extension);
                    useExtension("KHR_materials_emissive_strength");
                }
            }
            material.doubleSided = source.doubleSided;
            model_.materials.push_back(material);
        }
    }

    void addTriangles() {
        const Triangles& triangles = scene_.triangles;
        if (triangles.indices.empty()) return;
        Bounds3f bounds;
        for (const Vec3& p : triangles.positions) bounds.extend(p);
        int positions = addAccessor(triangles.positions.data(), triangles.positions.size() * sizeof(Vec3),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                    triangles.positions.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
        model_.accessors[positions].minValues = {bounds.lower.x, bounds.lower.y, bounds.lower.z};
        model_.accessors[positions].maxValues = {bounds.upper.x, bounds.upper.y, bounds.upper.z};
        int normals = -1;
        if (!triangles.normals.empty())
            normals = addAccessor(triangles.normals.data(), triangles.normals.size() * sizeof(Vec3),
                                  TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                  triangles.normals.size(), TINYGLTF_TARGET_ARRAY_BUFFER);

        tinygltf::Mesh mesh;
        mesh.name = "triangles";
        for (uint32_t material = 0; material < std::max<size_t>(scene_.materials.size(), 1); ++material) {
            std::vector<uint32_t> indices;
            for (uint32_t t = 0; t < triangles.indices.size(); ++t)
                if (triangles.material[t] == material)
                    indices.insert(indices.end(), triangles.indices[t].begin(), triangles.indices[t].end());
            if (indices.empty()) continue;
            tinygltf::Primitive primitive;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            primitive.attributes["POSITION"] = positions;
            if (normals >= 0) primitive.attributes["NORMAL"] = normals;
            primitive.indices = addAccessor(indices.data(), indices.size() * sizeof(uint32_t),
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                            indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            if (material < scene_.materials.size()) primitive.material = static_cast<int>(material);
            mesh.primitives.push_back(primitive);
        }
        model_.meshes.push_back(mesh);
        tinygltf::Node node;
        node.name = "triangles";
        node.mesh = static_cast<int>(model_.meshes.size()) - 1;
        addNode(node);
    }

    void addCamera(const Camera& source) {
        tinygltf::Camera camera;
        camera.name = source.name;
        camera.type = "perspective";
        camera.perspective.yfov = source.yfov;
        camera.perspective.aspectRatio = source.aspectRatio;
        camera.perspective.znear = kZNear;
        camera.perspective.zfar = farPlane(source.position);
        model_.cameras.push_back(camera);

        // A glTF camera looks down its local -Z with +Y up.
        DVec3 back = -glm::normalize(source.forward);
        DVec3 right = glm::normalize(glm::cross(source.up, back));
        DVec3 up = glm::cross(back, right);
        glm::dquat rotation = glm::quat_cast(glm::dmat3(right, up, back));
        tinygltf::Node node;
        node.name = source.name;
        node.camera = static_cast<int>(model_.cameras.size()) - 1;
        node.translation = {source.position.x, source.position.y, source.position.z};
        node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
        addNode(node);
    }

    // rtlab's rays are unbounded and it never reads zfar, but tinygltf always writes it and glTF
    // requires zfar > znear when present (0, tinygltf's "infinite", is invalid): a plane beyond
    // everything in the scene keeps other tools' views complete.
    double farPlane(const DVec3& eye) const {
        Bounds3f bounds = scene_.bounds();
        double farthest = 0.0;
        if (!bounds.isEmpty())
            for (int corner = 0; corner < 8; ++corner) {
                DVec3 p(bounds[corner & 1].x, bounds[(corner >> 1) & 1].y, bounds[(corner >> 2) & 1].z);
                farthest = std::max(farthest, glm::length(p - eye));
            }
        return std::max(2.0 * farthest, 1000.0 * kZNear);
    }

    void addLight(const PointLight& source) {
        // glTF point lights are in candela: colour times intensity = W/sr * 683.
        float peak = std::max({source.intensity.x, source.intensity.y, source.intensity.z});
        tinygltf::Light light;
        light.name = source.name;
        light.type = "point";
        Vec3 colour = peak > 0.0f ? source.intensity / peak : Vec3(1.0f);
        light.color = {colour.x, colour.y, colour.z};
        light.intensity = static_cast<double>(peak) * kLumensPerWatt;
        model_.lights.push_back(light);
        useExtension("KHR_lights_punctual");

        tinygltf::Node node;
        node.name = source.name;
        node.translation = {source.position.x, source.position.y, source.position.z};
        tinygltf::Value::Object reference{{"light", tinygltf::Value(static_cast<int>(model_.lights.size()) - 1)}};
        node.extensions["KHR_lights_punctual"] = tinygltf::Value(reference);
        addNode(node);
    }

    void addSphere(const Sphere& source) {
        tinygltf::Node node;
        node.name = "sphere";
        node.translation = {source.centre.x, source.centre.y, source.centre.z};
        tinygltf::Value::Object sphere{{"radius", tinygltf::Value(double(source.radius))},
                                       {"material", tinygltf::Value(static_cast<int>(source.material))}};
        tinygltf::Value::Object rtlab{{"sphere", tinygltf::Value(sphere)}};
        node.extras = tinygltf::Value(tinygltf::Value::Object{{"rtlab", tinygltf::Value(rtlab)}});
        addNode(node);
    }

    void useExtension(const std::string& name) {
        auto& used = model_.extensionsUsed;
        if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
    }

    const Scene& scene_;
    tinygltf::Model model_;
};

}  // namespace

void writeGltf(const Scene& scene, const std::string& path) {
    tinygltf::Model model = GltfBuilder(scene).build();
    model.buffers[0].name = "data";
    bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, path, /*embedImages=*/true, /*embedBuffers=*/true,
                                     /*prettyPrint=*/!binary, binary))
        throw Error(path + ": cannot write the glTF file");
}

}  // namespace rtlab
