// writeCaseViewer (case_view.h): a CaseView into one folder with index.html. The page's numbers
// go into one ViewerBlob, its strings into one JSON object; both are inlined into the page in
// elements no browser runs, and read there with JSON.parse and typed arrays.
#include "viewer/case_view.h"

#include "framework/accel/structure_drawing.h"
#include "framework/core/error.h"
#include "framework/core/sha256.h"
#include "framework/core/untrusted_text.h"
#include "viewer/page_assets.h"
#include "viewer/structure_selection.h"
#include "viewer/trace_nodes.h"
#include "viewer/viewer_blob.h"
#include "viewer/viewer_folder.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <fstream>

namespace rtlab::viewer {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Every string from a CaseView: made valid, visible text (framework/core/untrusted_text.h) and cut.
std::string text(const std::string& s, const ViewerLimits& limits) {
    return grader::truncateUtf8(grader::escapeUntrusted(s, grader::TextLayout::Lines), limits.maxTextBytes);
}

// A number for the JSON: non-finite values (a miss at +inf, a student's NaN) become null.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// Quantises coordinates to 16 bits over a frame, rounding lower corners down and upper corners
// up, so a quantised box still holds what the original held.
struct Quantiser {
    Vec3 lower{0.0f}, scale{1.0f};

    explicit Quantiser(const Bounds3f& frame) {
        lower = frame.lower;
        Vec3 extent = frame.upper - frame.lower;
        for (int a = 0; a < 3; ++a) scale[a] = extent[a] > 0.0f ? 65535.0f / extent[a] : 0.0f;
    }
    uint16_t down(float v, int a) const { return clampQ(std::floor((double(v) - lower[a]) * scale[a])); }
    uint16_t up(float v, int a) const { return clampQ(std::ceil((double(v) - lower[a]) * scale[a])); }
    static uint16_t clampQ(double q) { return static_cast<uint16_t>(std::clamp(std::isnan(q) ? 0.0 : q, 0.0, 65535.0)); }
};

bool finiteBox(const Bounds3f& b) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(b.lower[a]) || !std::isfinite(b.upper[a]) || b.lower[a] > b.upper[a]) return false;
    return true;
}

// The frame every quantised coordinate is relative to: the scene's and the structure's boxes.
Bounds3f frameOf(const CaseView& view) {
    Bounds3f frame;
    if (view.scene && view.scene->primitiveCount() > 0) frame.extend(view.scene->bounds());
    if (view.structure && !view.structure->nodes.empty() && finiteBox(view.structure->nodes[0].bounds))
        frame.extend(view.structure->nodes[0].bounds);
    if (view.dda && finiteBox(view.dda->bounds)) frame.extend(view.dda->bounds);
    if (!finiteBox(frame)) frame = Bounds3f(Vec3(-1.0f), Vec3(1.0f));
    return frame;
}

void addGeometry(const Scene& scene, const Quantiser& q, const ViewerLimits& limits, ViewerBlob& blob, json& meta) {
    const Triangles& t = scene.triangles;
    meta["triangles"] = t.indices.size();
    meta["spheres"] = scene.spheres.size();
    if (t.indices.size() > limits.maxTriangles) {
        meta["geometryNote"] = "the scene's " + std::to_string(t.indices.size()) + " triangles are more than a page draws (" +
                               std::to_string(limits.maxTriangles) + ")";
        return;
    }
    std::vector<uint16_t> positions;
    positions.reserve(t.positions.size() * 3);
    for (const Vec3& p : t.positions)
        for (int a = 0; a < 3; ++a) positions.push_back(Quantiser::clampQ(std::round((double(p[a]) - q.lower[a]) * q.scale[a])));
    blob.add("mesh.pos", positions);
    std::vector<uint32_t> indices;
    indices.reserve(t.indices.size() * 3);
    for (const auto& tri : t.indices)
        for (uint32_t i : tri) indices.push_back(i);
    blob.add("mesh.index", indices);
    std::vector<float> spheres;
    for (const Sphere& s : scene.spheres) spheres.insert(spheres.end(), {s.centre.x, s.centre.y, s.centre.z, s.radius});
    blob.add("mesh.sphere", spheres);
}

// The trace of one ray, as parallel arrays, with the node each operation was about.
void addTrace(const std::string& prefix, const TraversalTrace& trace, const std::vector<uint32_t>& nodes, const NodeSelection& selection,
              const ViewerLimits& limits, ViewerBlob& blob, json& meta) {
    size_t count = std::min(trace.ops.size(), limits.maxTraceOps);
    std::vector<uint8_t> kind(count), hit(count);
    std::vector<uint32_t> index(count), node(count, kNoNode);
    std::vector<float> t(count), tFar(count), boxes;
    for (size_t i = 0; i < count; ++i) {
        const TraceOp& op = trace.ops[i];
        kind[i] = static_cast<uint8_t>(op.kind);
        hit[i] = op.hit;
        index[i] = op.index;
        t[i] = op.t;
        tFar[i] = op.tFar;
        if (i < nodes.size() && nodes[i] != kUnresolved && nodes[i] < selection.shippedOf.size()) node[i] = selection.shippedOf[nodes[i]];
        if (op.kind == TraceOpKind::BoxTest && op.index < trace.boxes.size()) {
            const Bounds3f& b = trace.boxes[op.index];
            boxes.insert(boxes.end(), {b.lower.x, b.lower.y, b.lower.z, b.upper.x, b.upper.y, b.upper.z});
        } else if (op.kind == TraceOpKind::BoxTest) {
            boxes.insert(boxes.end(), 6, std::nanf(""));
        }
    }
    blob.add(prefix + ".kind", kind);
    blob.add(prefix + ".hit", hit);
    blob.add(prefix + ".index", index);
    blob.add(prefix + ".t", t);
    blob.add(prefix + ".tfar", tFar);
    blob.add(prefix + ".node", node);
    blob.add(prefix + ".box", boxes);
    meta["ops"] = count;
    meta["dropped"] = trace.dropped + (trace.ops.size() - count);
}

json answerJson(const RayAnswer& a) {
    json j;
    j["kind"] = a.kind == RayAnswer::Kind::None ? "none" : a.kind == RayAnswer::Kind::Closest ? "closest" : "any";
    j["hit"] = a.hit;
    j["t"] = number(a.t);
    j["prim"] = a.prim == kNoHit ? json(nullptr) : json(a.prim);
    return j;
}

void addStructure(const CaseView& view, const Quantiser& q, const std::vector<std::vector<uint32_t>>& studentNodes,
                  const std::vector<std::vector<uint32_t>>& expectedNodes, NodeSelection& selection, ViewerBlob& blob, json& meta) {
    const StructureView& s = *view.structure;
    // The style first (with only the root drawn), to know what the budget counts; then the
    // drawing of the nodes the page carries.
    auto draw = [&](const NodeMask& drawn) { return view.draw ? view.draw(s, drawn) : drawLevels(s, drawn); };
    NodeMask rootOnly(s.nodes.size(), false);
    if (!rootOnly.empty()) rootOnly[0] = true;
    StructureDrawing drawing = draw(rootOnly);
    std::vector<uint32_t> wanted;
    std::vector<bool> visited(s.nodes.size(), false);
    for (const auto* lists : {&studentNodes, &expectedNodes})
        for (const std::vector<uint32_t>& list : *lists)
            for (uint32_t v : list)
                if (v < s.nodes.size() && !visited[v]) {
                    visited[v] = true;
                    wanted.push_back(v);
                }
    if (view.dda && s.nodes.size() > 0) {
        // The DDA's cells are nodes of a grid's view: root child cellIndex.
        const std::array<int, 3>& r = view.dda->resolution;
        size_t cells = size_t(r[0]) * r[1] * r[2];
        if (s.nodes[0].childCount == cells && size_t(s.nodes[0].firstChild) + cells <= s.children.size())
            for (const auto* list : {&view.dda->expected, &view.dda->student})
                for (size_t k = 0; k < std::min(list->size(), view.limits.maxDdaCells); ++k) {
                    const GridCell& c = (*list)[k];
                    if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[0] >= r[0] || c[1] >= r[1] || c[2] >= r[2]) continue;
                    uint32_t v = s.children[s.nodes[0].firstChild + (size_t(c[2]) * r[1] + c[1]) * r[0] + c[0]];
                    if (v < s.nodes.size()) wanted.push_back(v);
                }
    }
    size_t budget = drawing.style == DrawingStyle::Cells ? view.limits.maxCells : view.limits.maxNodes;
    selection = selectNodes(s, drawing.style, budget, wanted);
    NodeMask carried(s.nodes.size(), false);
    for (uint32_t v : selection.nodes) carried[v] = true;
    drawing = draw(carried);

    const size_t count = selection.nodes.size();
    std::vector<uint32_t> id(count), primCount(count), primStart(count, kNoNode), prims;
    std::vector<uint8_t> flags(count);
    std::vector<uint16_t> boxes;
    boxes.reserve(count * 6);
    std::vector<float> values;
    const size_t maxPrims = size_t(1) << 20;
    for (size_t i = 0; i < count; ++i) {
        uint32_t v = selection.nodes[i];
        const StructureNode& node = s.nodes[v];
        id[i] = v;
        primCount[i] = node.primCount;
        bool leaf = node.childCount == 0;
        bool box = finiteBox(node.bounds);
        flags[i] = uint8_t((leaf ? 1 : 0) | (visited[v] ? 2 : 0) | (box ? 0 : 4));
        for (int a = 0; a < 3; ++a) boxes.push_back(box ? q.down(node.bounds.lower[a], a) : 0);
        for (int a = 0; a < 3; ++a) boxes.push_back(box ? q.up(node.bounds.upper[a], a) : 0);
        bool listed = uint64_t(node.firstPrim) + node.primCount <= s.primIndices.size();
        if (leaf && listed && prims.size() + node.primCount <= maxPrims && (visited[v] || node.primCount <= 64)) {
            primStart[i] = static_cast<uint32_t>(prims.size());
            prims.insert(prims.end(), s.primIndices.begin() + node.firstPrim, s.primIndices.begin() + node.firstPrim + node.primCount);
        }
        if (drawing.values.size() == s.nodes.size()) values.push_back(drawing.values[v]);
    }
    blob.add("node.id", id);
    blob.add("node.parent", selection.parent);
    blob.add("node.depth", selection.depth);
    blob.add("node.flags", flags);
    blob.add("node.count", primCount);
    blob.add("node.box", boxes);
    blob.add("node.primStart", primStart);
    blob.add("node.prims", prims);
    if (!values.empty()) blob.add("node.value", values);
    // Planes of the carried nodes, as polygons.
    std::vector<uint32_t> planeNode, planeStart = {0};
    std::vector<float> planeVerts;
    for (const DrawnPlane& p : drawing.planes) {
        if (p.node >= selection.shippedOf.size() || selection.shippedOf[p.node] == kNoNode) continue;
        planeNode.push_back(selection.shippedOf[p.node]);
        for (const Vec3& c : p.polygon) planeVerts.insert(planeVerts.end(), {c.x, c.y, c.z});
        planeStart.push_back(static_cast<uint32_t>(planeVerts.size() / 3));
    }
    blob.add("plane.node", planeNode);
    blob.add("plane.start", planeStart);
    blob.add("plane.verts", planeVerts);

    static const char* kStyles[] = {"levels", "cells", "planes"};
    json& m = meta["structure"];
    m["style"] = kStyles[static_cast<int>(drawing.style)];
    m["boxesMeaningful"] = drawing.boxesMeaningful;
    m["valueName"] = drawing.valueName;
    m["nodes"] = s.nodes.size();
    m["reachable"] = selection.reachable;
    m["carried"] = count;
    m["maxDepth"] = selection.maxDepth;
    m["completeDepth"] = selection.completeDepth;
    m["malformed"] = selection.malformed;
    m["references"] = s.primIndices.size();
}

void addRays(const CaseView& view, const NodeSelection& selection, const std::vector<std::vector<uint32_t>>& studentNodes,
             const std::vector<std::vector<uint32_t>>& expectedNodes, ViewerBlob& blob, json& meta) {
    std::vector<float> rays;
    json list = json::array();
    for (size_t r = 0; r < studentNodes.size(); ++r) {
        const RayCase& c = view.rays[r];
        rays.insert(rays.end(), {c.ray.origin.x, c.ray.origin.y, c.ray.origin.z, c.ray.direction.x, c.ray.direction.y, c.ray.direction.z,
                                 c.ray.tMin, c.ray.tMax});
        json j;
        j["label"] = text(c.label, view.limits);
        j["student"] = answerJson(c.student);
        j["expected"] = answerJson(c.expected);
        j["expectedSource"] = text(c.expectedSource, view.limits);
        if (c.studentTrace) addTrace("trace." + std::to_string(r) + ".s", *c.studentTrace, studentNodes[r], selection, view.limits, blob, j["studentTrace"]);
        if (c.expectedTrace)
            addTrace("trace." + std::to_string(r) + ".e", *c.expectedTrace, expectedNodes[r], selection, view.limits, blob, j["expectedTrace"]);
        if (c.studentTrace && c.expectedTrace) j["firstDifference"] = firstDifference(*c.studentTrace, *c.expectedTrace);
        list.push_back(j);
    }
    if (!rays.empty()) blob.add("ray.data", rays);
    meta["rays"] = list;
}

void addDda(const DdaCells& dda, const ViewerLimits& limits, ViewerBlob& blob, json& meta) {
    auto flatten = [&](const std::vector<GridCell>& cells) {
        std::vector<int32_t> out;
        for (size_t k = 0; k < std::min(cells.size(), limits.maxDdaCells); ++k) out.insert(out.end(), cells[k].begin(), cells[k].end());
        return out;
    };
    blob.add("dda.expected", flatten(dda.expected));
    blob.add("dda.student", flatten(dda.student));
    std::vector<float> frame = {dda.bounds.lower.x, dda.bounds.lower.y, dda.bounds.lower.z, dda.bounds.upper.x, dda.bounds.upper.y, dda.bounds.upper.z};
    blob.add("dda.bounds", frame);
    std::vector<int32_t> resolution(dda.resolution.begin(), dda.resolution.end());
    blob.add("dda.resolution", resolution);
    meta["dda"] = {{"ray", dda.ray}, {"expected", dda.expected.size()}, {"student", dda.student.size()}};
}

void addImages(const ImageSet& images, const fs::path& folder, const ViewerLimits& limits, ViewerBlob& blob, json& meta) {
    json& m = meta["images"];
    m["width"] = images.width;
    m["height"] = images.height;
    m["legend"] = text(images.legend, limits);
    for (auto [key, path] : {std::pair{"render", &images.render}, {"heat", &images.heatMap}, {"reference", &images.reference},
                             {"difference", &images.difference}}) {
        if (path->empty()) continue;
        std::string name = std::string(key) + ".png";
        std::error_code ec;
        fs::copy_file(*path, folder / name, ec);
        if (ec) throw Error(path->string() + ": cannot copy into the viewer: " + ec.message());
        m[key] = name;
    }
    size_t pixels = size_t(std::max(images.width, 0)) * size_t(std::max(images.height, 0));
    if (images.hitT.size() == pixels) blob.add("pixel.t", images.hitT);
    if (!images.lights.empty() && images.shadowBlocked.size() == pixels * images.lights.size()) {
        blob.add("pixel.shadow", images.shadowBlocked);
        std::vector<float> lights;
        for (const Vec3& p : images.lights) lights.insert(lights.end(), {p.x, p.y, p.z});
        blob.add("light.pos", lights);
    }
    const CameraFilm& f = images.film;
    std::vector<double> film = {f.origin.x,  f.origin.y, f.origin.z, f.forward.x, f.forward.y, f.forward.z, f.right.x,
                                f.right.y,   f.right.z,  f.up.x,     f.up.y,      f.up.z,      f.width,     f.height};
    blob.add("film", film);
    if (images.selectedPixel) m["selected"] = {(*images.selectedPixel)[0], (*images.selectedPixel)[1]};
    if (!images.pixelCommand.empty()) meta["pixelCommand"] = text(images.pixelCommand, limits);
}

void addRadiometry(const CaseView& view, ViewerBlob& blob, json& meta) {
    json samplers = json::array();
    for (size_t i = 0; i < view.samplers.size(); ++i) {
        const SamplerPanel& s = view.samplers[i];
        std::string prefix = "a6.s." + std::to_string(i);
        size_t n = std::min({s.unitSquare.size(), s.mapped.size(), view.limits.maxSamplerPoints});
        std::vector<float> u, mapped;
        for (size_t k = 0; k < n; ++k) {
            u.insert(u.end(), {s.unitSquare[k].x, s.unitSquare[k].y});
            mapped.insert(mapped.end(), {s.mapped[k].x, s.mapped[k].y, s.mapped[k].z});
        }
        blob.add(prefix + ".u", u);
        blob.add(prefix + ".mapped", mapped);
        blob.add(prefix + ".observed", s.observed);
        blob.add(prefix + ".expected", s.expected);
        std::vector<float> shape = {s.triangle[0].x, s.triangle[0].y, s.triangle[0].z, s.triangle[1].x, s.triangle[1].y, s.triangle[1].z,
                                    s.triangle[2].x, s.triangle[2].y, s.triangle[2].z, s.origin.x, s.origin.y, s.origin.z, s.cosThetaMax};
        blob.add(prefix + ".shape", shape);
        samplers.push_back({{"name", text(s.name, view.limits)}, {"domain", text(s.domain, view.limits)},
                            {"cells", text(s.cellsNote, view.limits)}, {"chiSquare", number(s.chiSquare)}, {"p", number(s.pValue)},
                            {"dof", s.dof}, {"error", text(s.error, view.limits)}, {"points", n}, {"rows", s.rows}, {"cols", s.cols},
                            {"zMin", number(s.zMin)}});
    }
    json estimators = json::array();
    for (size_t i = 0; i < view.estimators.size(); ++i) {
        const EstimatorCurve& e = view.estimators[i];
        std::string prefix = "a6.e." + std::to_string(i);
        blob.add(prefix + ".n", e.samples);
        blob.add(prefix + ".error", e.rmsError);
        estimators.push_back({{"name", text(e.name, view.limits)}, {"slope", number(e.slope)}, {"error", text(e.error, view.limits)}});
    }
    meta["samplers"] = samplers;
    meta["estimators"] = estimators;
}

// JSON for a <script type="application/json"> element: '<', '>' and '&' as \u escapes, which
// only occur inside JSON strings, so no "</script>" can end the element early.
std::string scriptSafeJson(const json& j) {
    std::string dumped = j.dump(-1, ' ', false, json::error_handler_t::replace), out;
    out.reserve(dumped.size());
    for (char c : dumped) {
        if (c == '<') out += "\\u003c";
        else if (c == '>') out += "\\u003e";
        else if (c == '&') out += "\\u0026";
        else out += c;
    }
    return out;
}

// The template with each marker replaced by its content, every marker found in the template
// itself (never in content already put in).
std::string fillTemplate(std::string_view page, const std::vector<std::pair<std::string, std::string_view>>& parts) {
    std::vector<std::pair<size_t, size_t>> at;  // template position, part
    for (size_t i = 0; i < parts.size(); ++i) {
        size_t p = page.find(parts[i].first);
        if (p == std::string_view::npos) throw Error("viewer: the page template has no " + parts[i].first);
        at.emplace_back(p, i);
    }
    std::sort(at.begin(), at.end());
    std::string out;
    size_t from = 0;
    for (auto [p, i] : at) {
        out.append(page.substr(from, p - from));
        out.append(parts[i].second);
        from = p + parts[i].first.size();
    }
    out.append(page.substr(from));
    return out;
}

// A file inlined into a <script> element must not close it.
std::string_view scriptSafe(std::string_view code, const char* what) {
    std::string lower(code.size(), ' ');
    std::transform(code.begin(), code.end(), lower.begin(), [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
    if (lower.find("</script") != std::string::npos || lower.find("<!--") != std::string::npos)
        throw Error(std::string("viewer: ") + what + " cannot be inlined into a page (it contains </script or <!--)");
    return code;
}

// The page's policy: only its own three scripts run (by their SHA-256), no eval, no inline event
// handler, no network; images from its folder.
std::string contentPolicy(std::initializer_list<std::string_view> scripts) {
    std::string policy = "default-src 'none'; script-src";
    for (std::string_view script : scripts) {
        std::string hex = sha256Hex(script);
        std::vector<uint8_t> digest;
        for (size_t i = 0; i + 1 < hex.size(); i += 2) digest.push_back(static_cast<uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
        policy += " 'sha256-" + base64(digest) + "'";
    }
    return policy + "; style-src 'unsafe-inline'; img-src 'self' file: data:";
}

}  // namespace

void writeCaseViewer(const fs::path& dir, const CaseView& view) {
    ViewerFolder folder(dir);
    const ViewerLimits& limits = view.limits;
    ViewerBlob blob;
    json meta;
    meta["format"] = 1;
    meta["title"] = text(view.title, limits);
    json notes = json::array();
    for (size_t i = 0; i < std::min<size_t>(view.notes.size(), 64); ++i) notes.push_back(text(view.notes[i], limits));
    meta["notes"] = notes;
    meta["accelerator"] = text(view.acceleratorName, limits);

    Bounds3f frame = frameOf(view);
    Quantiser q(frame);
    blob.add("frame", std::vector<float>{frame.lower.x, frame.lower.y, frame.lower.z, frame.upper.x, frame.upper.y, frame.upper.z});
    if (view.scene) addGeometry(*view.scene, q, limits, blob, meta);

    // Each trace's operations resolved to nodes of the structure, then the nodes to carry.
    size_t rayCount = std::min(view.rays.size(), limits.maxRays);
    std::vector<std::vector<uint32_t>> studentNodes(rayCount), expectedNodes(rayCount);
    NodeSelection selection;
    if (view.structure) {
        std::array<int, 3> resolution = view.dda ? view.dda->resolution : std::array<int, 3>{0, 0, 0};
        for (size_t r = 0; r < rayCount; ++r) {
            const RayCase& c = view.rays[r];
            bool ddaRay = view.dda && view.dda->ray == r;
            if (c.studentTrace)
                studentNodes[r] = resolveTraceNodes(*view.structure, *c.studentTrace, c.ray, ddaRay ? view.dda->student : std::vector<GridCell>{}, resolution);
            if (c.expectedTrace)
                expectedNodes[r] = resolveTraceNodes(*view.structure, *c.expectedTrace, c.ray, ddaRay ? view.dda->expected : std::vector<GridCell>{}, resolution);
        }
        addStructure(view, q, studentNodes, expectedNodes, selection, blob, meta);
    }
    addRays(view, selection, studentNodes, expectedNodes, blob, meta);
    if (view.rays.size() > rayCount) meta["notes"].push_back("showing " + std::to_string(rayCount) + " of " + std::to_string(view.rays.size()) + " rays");
    if (view.dda) addDda(*view.dda, limits, blob, meta);
    if (view.gridResolution) blob.add("grid.resolution", std::vector<int32_t>(view.gridResolution->begin(), view.gridResolution->end()));
    if (view.images) addImages(*view.images, folder.scratch(), limits, blob, meta);
    if (!view.samplers.empty() || !view.estimators.empty()) addRadiometry(view, blob, meta);

    const PageAssets& assets = pageAssets();
    std::string textJson = scriptSafeJson(meta), data = blob.deflatedBase64();
    std::string policy = contentPolicy({assets.three, assets.orbitControls, assets.script});
    std::string html = fillTemplate(assets.html, {{"<!--POLICY-->", policy},
                                                  {"<!--STYLE-->", assets.css},
                                                  {"<!--THREE-->", scriptSafe(assets.three, "three.min.js")},
                                                  {"<!--ORBIT-->", scriptSafe(assets.orbitControls, "OrbitControls.js")},
                                                  {"<!--SCRIPT-->", scriptSafe(assets.script, "viewer.js")},
                                                  {"<!--TEXT-->", textJson},
                                                  {"<!--DATA-->", data}});
    std::ofstream out(folder.scratch() / "index.html", std::ios::binary);
    out.write(html.data(), static_cast<std::streamsize>(html.size()));
    out.close();
    if (!out) throw Error(dir.string() + ": cannot write index.html");
    folder.commit();
}

}  // namespace rtlab::viewer
