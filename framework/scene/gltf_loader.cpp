// glTF 2.0 -> Scene. tinygltf parses the file; everything it hands over is treated as untrusted:
// every index, accessor, buffer view and buffer range is checked before it is read, so a
// malformed file ends in one rtlab::Error and never in an out-of-range read.
//
// What is read (docs/scenes.md): the default scene (else scene 0, else every root node), the
// node hierarchy (matrix or T*R*S, composed parent*child in double precision), TRIANGLES
// primitives (indexed with u8/u16/u32 or not), NORMAL, perspective cameras, KHR_lights_punctual
// point lights (in candela, or in watts from extras.rtlab.power), baseColorFactor,
// emissiveFactor with KHR_materials_emissive_strength, doubleSided, and analytic spheres from
// extras.rtlab.sphere. Textures are never used, so images are never decoded.
//
// Limits on input: before tinygltf sees a document, its size, its JSON nesting and every
// buffer's byteLength are checked against what the file can hold, and before anything is
// instantiated the node graph is checked to be a forest of bounded depth. A hostile file ends in
// one line naming it and the problem, never in a large allocation or a deep recursion.
#include "framework/scene/gltf_loader.h"

#include "framework/core/error.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <string_view>

namespace rtlab {
namespace {

constexpr const char* kLightsExtension = "KHR_lights_punctual";
constexpr const char* kEmissiveStrengthExtension = "KHR_materials_emissive_strength";
constexpr const char* kSphereFeature = "extras.rtlab.sphere";
constexpr const char* kPowerFeature = "extras.rtlab.power";
constexpr const char* kNormalsFeature = "vertex normals (smooth shading)";

// Relative tolerance for "this transform scales uniformly" (spheres stay spheres).
constexpr double kUniformScaleTolerance = 1e-6;

// The largest file the loader reads: the scene itself and every file it names. The largest
// scene rtlab writes (the sphereflake as .gltf) is about 40 MB.
constexpr uint64_t kMaxFileBytes = uint64_t{1} << 30;
// JSON nesting of arrays and objects: glTF's own schema needs fewer than ten levels, and
// tinygltf copies extras and extensions recursively, so a deeper document is refused.
constexpr int kMaxJsonDepth = 64;
// Levels of the node hierarchy, far more than any modelling tool writes.
constexpr size_t kMaxNodeDepth = 1000;

// We never use textures: accept every image without decoding it.
bool skipImageDecoding(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                       const unsigned char*, int, void*) {
    return true;
}

// tinygltf's messages may quote a whole data URI: keep the first line, and only its start.
std::string firstLine(const std::string& text) {
    constexpr size_t kMaxLength = 400;
    std::string line = text.substr(0, text.find_first_of("\r\n"));
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.size() > kMaxLength) line = line.substr(0, kMaxLength) + "...";
    return line;
}

bool startsWithGlbMagic(std::span<const unsigned char> bytes) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

uint32_t readLittleEndian32(std::span<const unsigned char> bytes, size_t offset) {
    return uint32_t{bytes[offset]} | uint32_t{bytes[offset + 1]} << 8 | uint32_t{bytes[offset + 2]} << 16 |
           uint32_t{bytes[offset + 3]} << 24;
}

// The whole file, refused beyond `limit` bytes or when it is not a regular file (a FIFO or a
// device named by a hostile uri would block or never end).
bool readWholeFile(const std::string& path, uint64_t limit, std::vector<unsigned char>* out, std::string* problem) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        *problem = "not a regular file";
        return false;
    }
    uintmax_t size = std::filesystem::file_size(path, error);
    if (error || size > limit) {
        *problem = error ? "cannot read its size"
                         : "beyond the loader's limit of " + std::to_string(kMaxFileBytes >> 20) +
                               " MiB for a scene and the files it names";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        *problem = "cannot open the file";
        return false;
    }
    out->resize(static_cast<size_t>(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        *problem = "read error";
        return false;
    }
    return true;
}

// tinygltf's test for the files a document names; its own opens them, which blocks on a FIFO.
bool referencedFileExists(const std::string& path, void*) {
    std::error_code error;
    return std::filesystem::exists(path, error);
}

// tinygltf's reader of the files a document names (buffers, and images, which it reads even
// though rtlab never decodes them). `budget` is what is left of kMaxFileBytes: a document that
// names one large file a hundred times is refused, not read a hundred times.
bool readReferencedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* budget) {
    uint64_t& remaining = *static_cast<uint64_t*>(budget);
    std::string problem;
    if (readWholeFile(path, remaining, out, &problem)) {
        remaining -= out->size();
        return true;
    }
    if (err) *err += problem + "\n";  // tinygltf puts "File read error : PATH : " in front
    return false;
}

// The parts of a .glb container: its JSON chunk and the size of its BIN chunk (0 if none).
struct GlbChunks {
    std::string_view json;
    uint64_t binBytes = 0;
};

// Checks the 12-byte header and the chunk table, so that nothing after it reads past the file.
std::optional<GlbChunks> splitGlb(std::span<const unsigned char> bytes, std::string* problem) {
    constexpr size_t kHeaderBytes = 12, kChunkHeaderBytes = 8;
    constexpr uint32_t kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;
    if (bytes.size() < kHeaderBytes + kChunkHeaderBytes) {
        *problem = "GLB file of " + std::to_string(bytes.size()) + " bytes is too short for its header";
        return std::nullopt;
    }
    if (readLittleEndian32(bytes, 4) != 2) {
        *problem = "GLB version " + std::to_string(readLittleEndian32(bytes, 4)) + " is not supported (2 only)";
        return std::nullopt;
    }
    // Every size below is subtracted from this one, so it must cover at least the headers.
    uint64_t declared = readLittleEndian32(bytes, 8);
    if (declared > bytes.size() || declared < kHeaderBytes + kChunkHeaderBytes) {
        *problem = "GLB header declares " + std::to_string(declared) + " bytes, the file has " +
                   std::to_string(bytes.size());
        return std::nullopt;
    }
    GlbChunks chunks;
    uint64_t jsonBytes = readLittleEndian32(bytes, kHeaderBytes);
    if (readLittleEndian32(bytes, kHeaderBytes + 4) != kJsonChunk ||
        jsonBytes > declared - kHeaderBytes - kChunkHeaderBytes) {
        *problem = "GLB file does not start with a JSON chunk that fits in it";
        return std::nullopt;
    }
    chunks.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + kHeaderBytes + kChunkHeaderBytes,
                                   static_cast<size_t>(jsonBytes));
    uint64_t next = kHeaderBytes + kChunkHeaderBytes + jsonBytes;
    if (declared - next >= kChunkHeaderBytes && readLittleEndian32(bytes, next + 4) == kBinChunk) {
        chunks.binBytes = readLittleEndian32(bytes, next);
        if (chunks.binBytes > declared - next - kChunkHeaderBytes) {
            *problem = "GLB BIN chunk of " + std::to_string(chunks.binBytes) + " bytes reaches past the end of the file";
            return std::nullopt;
        }
    }
    return chunks;
}

// At most how many bytes a buffer's data can hold: a data URI's base64 payload, the GLB BIN
// chunk, or (for an external file) the file limit, which readReferencedFile enforces.
uint64_t bytesBehindBuffer(const nlohmann::json& buffer, size_t index, const GlbChunks* glb) {
    auto uri = buffer.find("uri");
    if (uri == buffer.end() || !uri->is_string()) return index == 0 && glb ? glb->binBytes : 0;
    const std::string& text = uri->get_ref<const std::string&>();
    if (text.rfind("data:", 0) != 0) return kMaxFileBytes;
    size_t comma = text.find(',');
    return comma == std::string::npos ? 0 : (text.size() - comma - 1) / 4 * 3 + 3;
}

// The checks made on the document before tinygltf parses it (see the top of this file).
void checkDocumentLimits(const std::string& path, std::span<const unsigned char> bytes, bool binary) {
    auto fail = [&](const std::string& problem) { throw Error(path + ": " + firstLine(problem)); };
    std::string problem;
    std::optional<GlbChunks> glb;
    std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (binary) {
        glb = splitGlb(bytes, &problem);
        if (!glb) fail(problem);
        text = glb->json;
    }
    auto limitDepth = [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
        if (depth > kMaxJsonDepth)
            fail("JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        return true;
    };
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text, limitDepth);
    } catch (const nlohmann::json::exception& e) {
        fail(e.what());
    }
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) return;
    const nlohmann::json& buffers = document["buffers"];
    for (size_t i = 0; i < buffers.size(); ++i) {
        if (!buffers[i].is_object() || !buffers[i].contains("byteLength")) continue;
        const nlohmann::json& length = buffers[i]["byteLength"];
        if (!length.is_number()) continue;  // tinygltf reports the type
        uint64_t available = bytesBehindBuffer(buffers[i], i, glb ? &*glb : nullptr);
        if (length.get<double>() > static_cast<double>(available))
            fail("buffer " + std::to_string(i) + ": byteLength " + length.dump() + " is more than the " +
                 std::to_string(available) + " bytes of data it can have");
    }
}

const char* modeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "unknown";
    }
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

bool isFinite(const DVec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// a + b and a * b on sizes, failing instead of wrapping around.
bool addFits(size_t a, size_t b, size_t* sum) { return !__builtin_add_overflow(a, b, sum); }
bool mulFits(size_t a, size_t b, size_t* product) { return !__builtin_mul_overflow(a, b, product); }

// The elements of one accessor, already checked to lie inside their buffer.
struct AccessorData {
    const unsigned char* first = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int componentType = 0;

    const unsigned char* element(size_t i) const { return first + i * stride; }
};

template <typename T>
T readUnaligned(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
}

DVec3 readFloat3(const AccessorData& data, size_t i) {
    const unsigned char* e = data.element(i);
    return DVec3(readUnaligned<float>(e), readUnaligned<float>(e + 4), readUnaligned<float>(e + 8));
}

uint32_t readIndex(const AccessorData& data, size_t i) {
    const unsigned char* e = data.element(i);
    switch (data.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *e;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return readUnaligned<uint16_t>(e);
        default: return readUnaligned<uint32_t>(e);
    }
}

// A node to instantiate with its world transform.
struct PendingNode {
    int index;
    glm::dmat4 parentToWorld;
};

class GltfReader {
public:
    GltfReader(const std::string& path, const tinygltf::Model& model, Scene& scene)
        : path_(path), model_(model), scene_(scene), visited_(model.nodes.size(), false) {}

    void read() {
        checkNodeGraph();
        checkVersionAndExtensions();
        readMaterials();
        for (const PendingNode& root : rootNodes()) visitTree(root);
        finish();
    }

private:
    // Names inside the problem come from the file: keep the message on one line whatever they hold.
    [[noreturn]] void fail(std::string problem) const {
        std::replace_if(problem.begin(), problem.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
        throw Error(path_ + ": " + problem);
    }

    void note(const std::string& feature) {
        if (std::find(scene_.featuresUsed.begin(), scene_.featuresUsed.end(), feature) ==
            scene_.featuresUsed.end())
            scene_.featuresUsed.push_back(feature);
    }

    template <typename T>
    const T& element(const std::vector<T>& list, int index, const char* what) const {
        if (index < 0 || static_cast<size_t>(index) >= list.size())
            fail(std::string(what) + " index " + std::to_string(index) + " is out of range (" +
                 std::to_string(list.size()) + " defined)");
        return list[static_cast<size_t>(index)];
    }

    static std::string describe(const std::string& kind, int index, const std::string& name) {
        return kind + " " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
    }

    void checkVersionAndExtensions() {
        const std::string& version = model_.asset.version;
        if (version.rfind("2.", 0) != 0)
            fail("glTF version '" + version + "' is not supported (glTF 2.0 only)");
        for (const std::string& extension : model_.extensionsRequired)
            if (extension != kLightsExtension && extension != kEmissiveStrengthExtension)
                fail("requires the glTF extension " + extension + ", which rtlab does not support");
        for (const std::string& extension : model_.extensionsUsed) note(extension);
    }

    void readMaterials() {
        for (size_t i = 0; i < model_.materials.size(); ++i) {
            const tinygltf::Material& source = model_.materials[i];
            std::string what = describe("material", static_cast<int>(i), source.name);
            Material material;
            material.name = source.name;
            const std::vector<double>& base = source.pbrMetallicRoughness.baseColorFactor;
            if (base.size() != 4) fail(what + ": baseColorFactor needs 4 numbers");
            material.albedo = Vec3(checkedColour(DVec3(base[0], base[1], base[2]), what));
            DVec3 emission(0.0);
            if (!source.emissiveFactor.empty()) {
                if (source.emissiveFactor.size() != 3) fail(what + ": emissiveFactor needs 3 numbers");
                emission = DVec3(source.emissiveFactor[0], source.emissiveFactor[1],
                                 source.emissiveFactor[2]);
            }
            auto strength = source.extensions.find(kEmissiveStrengthExtension);
            if (strength != source.extensions.end()) {
                const tinygltf::Value& factor = strength->second.Get("emissiveStrength");
                if (factor.IsNumber()) emission *= factor.GetNumberAsDouble();
                note(kEmissiveStrengthExtension);
            }
            material.emission = Vec3(checkedColour(emission, what));
            material.doubleSided = source.doubleSided;
            scene_.materials.push_back(material);
        }
    }

    DVec3 checkedColour(const DVec3& colour, const std::string& what) const {
        if (!isFinite(colour) || colour.x < 0.0 || colour.y < 0.0 || colour.z < 0.0)
            fail(what + ": colours must be finite and not negative");
        return colour;
    }

    // The material a primitive or sphere refers to; -1 means glTF's default material.
    uint32_t materialIndex(int index) {
        if (index < 0) {
            if (!defaultMaterial_) {
                defaultMaterial_ = static_cast<uint32_t>(scene_.materials.size());
                Material fallback;
                fallback.name = "default";
                scene_.materials.push_back(fallback);
            }
            return *defaultMaterial_;
        }
        element(model_.materials, index, "material");
        return static_cast<uint32_t>(index);
    }

    std::vector<PendingNode> rootNodes() const {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            roots = element(model_.scenes, sceneIndex, "scene").nodes;
        } else {
            // No scenes: every node that is nobody's child is a root.
            std::vector<bool> isChild(model_.nodes.size(), false);
            for (const tinygltf::Node& node : model_.nodes)
                for (int child : node.children)
                    if (child >= 0 && static_cast<size_t>(child) < isChild.size())
                        isChild[static_cast<size_t>(child)] = true;
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                if (!isChild[i]) roots.push_back(static_cast<int>(i));
        }
        std::vector<PendingNode> pending;
        for (int root : roots) pending.push_back({root, glm::dmat4(1.0)});
        return pending;
    }

    // glTF nodes form a forest: every child index is valid, no node has two parents, no parent
    // link closes a cycle, and no tree is deeper than kMaxNodeDepth. Checked over every node up
    // front, so a cycle that no scene reaches is still an error.
    void checkNodeGraph() const {
        const size_t count = model_.nodes.size();
        std::vector<int> parent(count, -1);
        for (size_t i = 0; i < count; ++i)
            for (int child : model_.nodes[i].children) {
                element(model_.nodes, child, "node");
                int& parentOfChild = parent[static_cast<size_t>(child)];
                if (parentOfChild != -1)
                    fail(describe("node", child, model_.nodes[static_cast<size_t>(child)].name) +
                         " has two parents (nodes " + std::to_string(parentOfChild) + " and " + std::to_string(i) + ")");
                parentOfChild = static_cast<int>(i);
            }
        // Depth 0 = not reached from a parentless node: with one parent each, such a node lies on
        // a cycle of parent links.
        std::vector<size_t> depth(count, 0);
        std::vector<size_t> stack;
        for (size_t root = 0; root < count; ++root) {
            if (parent[root] != -1) continue;
            depth[root] = 1;
            stack.push_back(root);
            while (!stack.empty()) {
                size_t i = stack.back();
                stack.pop_back();
                if (depth[i] > kMaxNodeDepth)
                    fail("the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " levels (at " +
                         describe("node", static_cast<int>(i), model_.nodes[i].name) + ")");
                for (int child : model_.nodes[i].children) {
                    depth[static_cast<size_t>(child)] = depth[i] + 1;
                    stack.push_back(static_cast<size_t>(child));
                }
            }
        }
        for (size_t i = 0; i < count; ++i)
            if (depth[i] == 0)
                fail(describe("node", static_cast<int>(i), model_.nodes[i].name) +
                     " is on a cycle of the node hierarchy (it would be reached twice)");
    }

    // Depth-first over the hierarchy with an explicit stack (deep files cannot overflow ours).
    // glTF nodes form strict trees, so reaching a node twice means a cycle or a shared child.
    void visitTree(const PendingNode& root) {
        std::vector<PendingNode> stack{root};
        while (!stack.empty()) {
            PendingNode current = stack.back();
            stack.pop_back();
            const tinygltf::Node& node = element(model_.nodes, current.index, "node");
            std::string what = describe("node", current.index, node.name);
            if (visited_[static_cast<size_t>(current.index)])
                fail(what + " is reached twice (a cycle, or a child with two parents)");
            visited_[static_cast<size_t>(current.index)] = true;

            glm::dmat4 toWorld = current.parentToWorld * localTransform(node, what);
            if (!isFinite(toWorld)) fail(what + ": the transform is not finite");
            instantiate(node, toWorld, what);
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
                stack.push_back({*child, toWorld});
        }
    }

    glm::dmat4 localTransform(const tinygltf::Node& node, const std::string& what) const {
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) fail(what + ": matrix needs 16 numbers");
            return glm::make_mat4(node.matrix.data());  // both column-major
        }
        glm::dmat4 m(1.0);
        if (!node.translation.empty()) {
            if (node.translation.size() != 3) fail(what + ": translation needs 3 numbers");
            m = glm::translate(m, glm::make_vec3(node.translation.data()));
        }
        if (!node.rotation.empty()) {
            if (node.rotation.size() != 4) fail(what + ": rotation needs 4 numbers");
            const std::vector<double>& q = node.rotation;  // glTF order: x, y, z, w
            glm::dquat rotation(q[3], q[0], q[1], q[2]);
            double length = glm::length(rotation);
            if (!(length > 0.0) || !std::isfinite(length))
                fail(what + ": rotation is not a valid quaternion");
            m = m * glm::mat4_cast(rotation / length);
        }
        if (!node.scale.empty()) {
            if (node.scale.size() != 3) fail(what + ": scale needs 3 numbers");
            m = glm::scale(m, glm::make_vec3(node.scale.data()));
        }
        return m;
    }

    void instantiate(const tinygltf::Node& node, const glm::dmat4& toWorld, const std::string& what) {
        if (node.mesh != -1) addMesh(node.mesh, toWorld);
        if (node.camera != -1) addCamera(node, toWorld);
        auto light = node.extensions.find(kLightsExtension);
        if (light != node.extensions.end()) addLight(light->second, toWorld, what);
        if (node.extras.Has("rtlab") && node.extras.Get("rtlab").Has("sphere"))
            addSphere(node.extras.Get("rtlab").Get("sphere"), toWorld, what);
    }

    // ---- meshes ------------------------------------------------------------------------------

    AccessorData accessorData(int index, const std::string& what) const {
        const tinygltf::Accessor& accessor = element(model_.accessors, index, "accessor");
        std::string where = what + ", accessor " + std::to_string(index);
        if (accessor.sparse.isSparse) fail(where + ": sparse accessors are not supported");
        if (accessor.bufferView < 0) fail(where + ": accessors without a bufferView are not supported");
        const tinygltf::BufferView& view = element(model_.bufferViews, accessor.bufferView, "bufferView");
        const tinygltf::Buffer& buffer = element(model_.buffers, view.buffer, "buffer");

        int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
        int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
        if (componentSize <= 0 || components <= 0) fail(where + ": unknown component type or type");
        size_t elementSize = static_cast<size_t>(componentSize) * static_cast<size_t>(components);
        size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
        if (stride < elementSize) fail(where + ": byteStride is smaller than one element");

        size_t viewEnd = 0;
        if (!addFits(view.byteOffset, view.byteLength, &viewEnd) || viewEnd > buffer.data.size())
            fail(where + ": bufferView " + std::to_string(accessor.bufferView) +
                 " reaches past the end of its buffer (" + std::to_string(buffer.data.size()) + " bytes)");
        AccessorData data;
        data.count = accessor.count;
        data.stride = stride;
        data.componentType = accessor.componentType;
        if (data.count == 0) return data;
        size_t span = 0, end = 0;
        if (!mulFits(stride, data.count - 1, &span) || !addFits(span, elementSize, &span) ||
            !addFits(accessor.byteOffset, span, &end) || end > view.byteLength)
            fail(where + ": " + std::to_string(data.count) + " elements reach past the end of bufferView " +
                 std::to_string(accessor.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
        data.first = buffer.data.data() + view.byteOffset + accessor.byteOffset;
        return data;
    }

    AccessorData float3Accessor(int index, const std::string& what, const char* attribute) const {
        const tinygltf::Accessor& accessor = element(model_.accessors, index, "accessor");
        if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || accessor.type != TINYGLTF_TYPE_VEC3)
            fail(what + ": " + attribute + " must be float VEC3 (quantized attributes are not supported)");
        return accessorData(index, what);
    }

    void addMesh(int meshIndex, const glm::dmat4& toWorld) {
        const tinygltf::Mesh& mesh = element(model_.meshes, meshIndex, "mesh");
        glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(toWorld)));
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            std::string what = describe("mesh", meshIndex, mesh.name) + " primitive " + std::to_string(p);
            if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) {
                note(std::string("skipped primitives of mode ") + modeName(primitive.mode));
                continue;
            }
            addPrimitive(primitive, toWorld, normalMatrix, what);
        }
    }

    void addPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& toWorld,
                      const glm::dmat3& normalMatrix, const std::string& what) {
        auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(what + ": has no POSITION attribute");
        AccessorData positions = float3Accessor(position->second, what, "POSITION");
        Triangles& out = scene_.triangles;
        size_t base = out.positions.size();
        if (positions.count > std::numeric_limits<uint32_t>::max() - base)
            fail(what + ": more than 2^32 vertices in the scene");

        for (size_t i = 0; i < positions.count; ++i) {
            DVec3 local = readFloat3(positions, i);
            Vec3 world = Vec3(DVec3(toWorld * glm::dvec4(local, 1.0)));  // rounded once
            if (!isFinite(local) || !isFinite(DVec3(world)))
                fail(what + ": vertex " + std::to_string(i) + " has a non-finite position");
            out.positions.push_back(world);
        }

        // Vertex normals; a triangle is smooth only when all three of its normals are usable.
        std::vector<bool> usableNormal(positions.count, false);
        auto normal = primitive.attributes.find("NORMAL");
        bool hasNormals = normal != primitive.attributes.end();
        if (hasNormals) {
            AccessorData normals = float3Accessor(normal->second, what, "NORMAL");
            if (normals.count != positions.count) fail(what + ": NORMAL and POSITION counts differ");
            for (size_t i = 0; i < normals.count; ++i) {
                DVec3 n = normalMatrix * readFloat3(normals, i);
                double length = glm::length(n);
                usableNormal[i] = std::isfinite(length) && length > 0.0;
                out.normals.push_back(usableNormal[i] ? Vec3(n / length) : Vec3(0.0f));
            }
            anyNormals_ = true;
            note(kNormalsFeature);
        } else {
            out.normals.resize(out.positions.size(), Vec3(0.0f));
        }

        uint32_t material = materialIndex(primitive.material);
        auto addTriangle = [&](uint32_t a, uint32_t b, uint32_t c) {
            for (uint32_t v : {a, b, c})
                if (v >= positions.count)
                    fail(what + ": index " + std::to_string(v) + " is out of range (" +
                         std::to_string(positions.count) + " vertices)");
            uint32_t offset = static_cast<uint32_t>(base);
            out.indices.push_back({a + offset, b + offset, c + offset});
            out.material.push_back(material);
            out.smooth.push_back(hasNormals && usableNormal[a] && usableNormal[b] && usableNormal[c]);
        };

        if (primitive.indices != -1) {
            const tinygltf::Accessor& accessor = element(model_.accessors, primitive.indices, "accessor");
            if (accessor.type != TINYGLTF_TYPE_SCALAR ||
                (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(what + ": indices must be unsigned byte, short or int scalars");
            AccessorData indices = accessorData(primitive.indices, what);
            if (indices.count % 3 != 0) fail(what + ": index count is not a multiple of 3");
            for (size_t i = 0; i < indices.count; i += 3)
                addTriangle(readIndex(indices, i), readIndex(indices, i + 1), readIndex(indices, i + 2));
        } else {
            if (positions.count % 3 != 0) fail(what + ": vertex count is not a multiple of 3");
            for (size_t i = 0; i < positions.count; i += 3)
                addTriangle(static_cast<uint32_t>(i), static_cast<uint32_t>(i + 1), static_cast<uint32_t>(i + 2));
        }
    }

    // ---- cameras, lights, spheres ------------------------------------------------------------

    void addCamera(const tinygltf::Node& node, const glm::dmat4& toWorld) {
        const tinygltf::Camera& source = element(model_.cameras, node.camera, "camera");
        std::string what = describe("camera", node.camera, source.name);
        if (source.type != "perspective") {
            note("skipped " + source.type + " cameras");
            return;
        }
        Camera camera;
        camera.name = !source.name.empty() ? source.name
                    : !node.name.empty()   ? node.name
                                           : "camera" + std::to_string(node.camera);
        camera.yfov = source.perspective.yfov;
        camera.aspectRatio = source.perspective.aspectRatio;
        if (!(camera.yfov > 0.0 && camera.yfov < std::numbers::pi))
            fail(what + ": yfov must lie between 0 and pi");
        if (!(camera.aspectRatio >= 0.0) || !std::isfinite(camera.aspectRatio))
            fail(what + ": aspectRatio must be positive");
        glm::dmat3 rotation(toWorld);
        camera.position = DVec3(toWorld[3]);
        DVec3 forward = rotation * DVec3(0.0, 0.0, -1.0);
        DVec3 up = rotation * DVec3(0.0, 1.0, 0.0);
        if (!(glm::length(glm::cross(forward, up)) > 0.0))
            fail(what + ": the node transform collapses the view direction");
        camera.forward = glm::normalize(forward);
        camera.up = glm::normalize(up);
        scene_.cameras.push_back(camera);
    }

    void addLight(const tinygltf::Value& extension, const glm::dmat4& toWorld, const std::string& what) {
        const tinygltf::Value& index = extension.Get("light");
        if (!index.IsInt()) fail(what + ": " + kLightsExtension + " needs an integer 'light'");
        const tinygltf::Light& source = element(model_.lights, index.Get<int>(), "light");
        std::string lightWhat = describe("light", index.Get<int>(), source.name);
        if (source.type != "point")
            fail(lightWhat + ": " + (source.type.empty() ? "untyped" : source.type) +
                 " lights are not supported (point lights only)");
        DVec3 colour(1.0);
        if (!source.color.empty()) {
            if (source.color.size() != 3) fail(lightWhat + ": color needs 3 numbers");
            colour = DVec3(source.color[0], source.color[1], source.color[2]);
        }
        if (!std::isfinite(source.intensity) || source.intensity < 0.0)
            fail(lightWhat + ": intensity must be finite and not negative");
        PointLight light;
        light.name = source.name;
        light.position = Vec3(DVec3(toWorld[3]));
        // glTF gives candela; a radiant flux in W may be given instead (extras.rtlab.power), for
        // an isotropic source I = Phi / 4 pi. The renderer works in W/sr (docs/conventions.md).
        if (source.extras.Has("rtlab") && source.extras.Get("rtlab").Has("power")) {
            const tinygltf::Value& power = source.extras.Get("rtlab").Get("power");
            if (!power.IsNumber() || !std::isfinite(power.GetNumberAsDouble()) || power.GetNumberAsDouble() < 0.0)
                fail(lightWhat + ": " + kPowerFeature + " must be a finite number of watts, not negative");
            light.intensity = Vec3(checkedColour(colour, lightWhat) * (power.GetNumberAsDouble() / (4.0 * std::numbers::pi)));
            note(kPowerFeature);
        } else {
            light.intensity = Vec3(checkedColour(colour, lightWhat) * source.intensity /
                                   static_cast<double>(kLumensPerWatt));
        }
        scene_.lights.push_back(light);
        note(kLightsExtension);
    }

    void addSphere(const tinygltf::Value& sphere, const glm::dmat4& toWorld, const std::string& what) {
        std::string where = what + ": " + kSphereFeature;
        const tinygltf::Value& radius = sphere.Get("radius");
        if (!radius.IsNumber() || !(radius.GetNumberAsDouble() > 0.0) ||
            !std::isfinite(radius.GetNumberAsDouble()))
            fail(where + ".radius must be a positive number");
        int material = -1;
        if (sphere.Has("material")) {
            if (!sphere.Get("material").IsInt()) fail(where + ".material must be an integer");
            material = sphere.Get("material").Get<int>();
        }
        // A sphere stays a sphere only under a similarity transform: M^T M = s^2 I.
        glm::dmat3 linear(toWorld);
        glm::dmat3 gram = glm::transpose(linear) * linear;
        double scale2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3.0;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                if (std::abs(gram[c][r] - (c == r ? scale2 : 0.0)) > kUniformScaleTolerance * scale2)
                    fail(where + " under a non-uniform scale or shear (spheres need a uniform scale)");
        Sphere out;
        out.centre = Vec3(DVec3(toWorld[3]));
        out.radius = static_cast<float>(radius.GetNumberAsDouble() * std::sqrt(scale2));
        if (!(out.radius > 0.0f) || !std::isfinite(out.radius)) fail(where + ": the world radius is not positive");
        out.material = materialIndex(material);
        scene_.spheres.push_back(out);
        note(kSphereFeature);
    }

    void finish() {
        // Normals stay parallel to positions while loading; without any there is nothing to keep.
        if (!anyNormals_) scene_.triangles.normals.clear();
    }

    const std::string& path_;
    const tinygltf::Model& model_;
    Scene& scene_;
    std::vector<bool> visited_;
    std::optional<uint32_t> defaultMaterial_;
    bool anyNormals_ = false;
};

}  // namespace

Scene loadGltf(const std::string& path) {
    std::vector<unsigned char> bytes;
    std::string problem;
    std::error_code missing;
    if (!std::filesystem::exists(path, missing)) throw Error(path + ": cannot open the file");
    if (!readWholeFile(path, kMaxFileBytes, &bytes, &problem)) throw Error(path + ": " + problem);
    bool binary = startsWithGlbMagic(bytes);
    // Without its magic a .glb would be parsed as JSON text and fail with a JSON parser's message
    // about the first byte; what the student needs to hear is that the file is no GLB at all.
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".glb" && !binary)
        throw Error(path + ": not a binary glTF (.glb) file: it does not start with the bytes 'glTF'");
    checkDocumentLimits(path, bytes, binary);

    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(skipImageDecoding, nullptr);
    uint64_t budget = kMaxFileBytes - bytes.size();
    parser.SetFsCallbacks({&referencedFileExists, &tinygltf::ExpandFilePath, &readReferencedFile,
                           &tinygltf::WriteWholeFile, &budget});
    tinygltf::Model model;
    std::string error, warning;
    std::string baseDirectory = std::filesystem::path(path).parent_path().string();
    auto size = static_cast<unsigned int>(bytes.size());  // at most kMaxFileBytes
    bool loaded = false;
    try {
        loaded = binary ? parser.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), size, baseDirectory)
                        : parser.LoadASCIIFromString(&model, &error, &warning, reinterpret_cast<const char*>(bytes.data()),
                                                     size, baseDirectory);
    } catch (const std::exception& e) {  // e.g. a JSON library exception tinygltf lets through
        error = e.what();
    }
    if (!loaded || !error.empty()) {
        problem = firstLine(error);
        throw Error(path + ": " + (problem.empty() ? "not a valid glTF 2.0 file" : problem));
    }

    Scene scene;
    scene.sourcePath = path;
    GltfReader(path, model, scene).read();
    return scene;
}

}  // namespace rtlab
