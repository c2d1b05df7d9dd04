// The viewer's C++ side (viewer/, docs/viewer.md): which node each step of a trace is about,
// where two traces part, which nodes a page carries, the planes a KD-tree and a BSP are drawn
// with, and the folder rules and escaping of writeCaseViewer. What the page does with it is
// tests/viewer/browser_test.py's part.
#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/bvh_accelerator.h"
#include "framework/accel/grid/grid_accelerator.h"
#include "framework/accel/structure_drawing.h"
#include "framework/core/error.h"
#include "framework/interface/a3_grid.h"
#include "framework/scene/gltf_loader.h"
#include "tests/output_dirs.h"
#include "viewer/case_view.h"
#include "viewer/structure_selection.h"
#include "viewer/trace_nodes.h"

#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <sstream>

namespace rtlab {
namespace {

namespace fs = std::filesystem;
using viewer::kUnresolved;

Scene cornellBox() { return loadGltf(std::string(RTLAB_SOURCE_DIR) + "/scenes/cornell-box.gltf"); }

struct Traced {
    Scene scene = cornellBox();
    PrimitiveSet primitives{scene};
    std::unique_ptr<Accelerator> accelerator;
    StructureView view;
    TraversalTrace trace;
    Hit hit;

    Traced(const std::string& name, const Ray& ray) {
        AcceleratorSpec spec;
        spec.name = name;
        accelerator = makeAccelerator(spec);
        accelerator->build(primitives);
        view = accelerator->structure();
        TraversalStats stats;
        stats.trace = &trace;
        hit = accelerator->intersect(ray, stats);
    }
};

const Ray kRay{Vec3(0.13f, 1.17f, 3.5f), Vec3(0.031f, -0.107f, -1.0f)};

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t occurrences(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("every box test of a BVH walk names its node, a node after its parent and once") {
    Traced t("bvh", kRay);
    std::vector<uint32_t> nodes = viewer::resolveTraceNodes(t.view, t.trace, kRay, {}, {0, 0, 0});
    std::vector<uint32_t> parent(t.view.nodes.size(), kUnresolved);
    for (uint32_t i = 0; i < t.view.nodes.size(); ++i)
        for (uint32_t c = 0; c < t.view.nodes[i].childCount; ++c) parent[t.view.children[t.view.nodes[i].firstChild + c]] = i;
    std::set<uint32_t> met;
    for (size_t i = 0; i < t.trace.ops.size(); ++i) {
        const TraceOp& op = t.trace.ops[i];
        if (op.kind != TraceOpKind::BoxTest) continue;
        REQUIRE(nodes[i] != kUnresolved);
        CHECK(t.view.nodes[nodes[i]].bounds.lower == t.trace.boxes[op.index].lower);
        CHECK(met.insert(nodes[i]).second);
        if (nodes[i] != 0) CHECK(met.count(parent[nodes[i]]) == 1);
    }
    // The primitive tests that follow a leaf's box test belong to that leaf.
    for (size_t i = 0; i < t.trace.ops.size(); ++i)
        if (t.trace.ops[i].kind == TraceOpKind::PrimitiveTest) {
            REQUIRE(nodes[i] != kUnresolved);
            const StructureNode& leaf = t.view.nodes[nodes[i]];
            CHECK(leaf.childCount == 0);
            auto first = t.view.primIndices.begin() + leaf.firstPrim;
            CHECK(std::find(first, first + leaf.primCount, t.trace.ops[i].index) != first + leaf.primCount);
        }
}

TEST_CASE("a grid's cell steps are the cells of its DDA walk, a KD-tree's leaves are found by their lists") {
    Traced g("grid", kRay);
    const UniformGrid& grid = dynamic_cast<const GridAccelerator&>(*g.accelerator).grid();
    float tEnter = 0.0f;
    REQUIRE(intersectBox(grid.bounds, RayInverse(kRay), kRay.tMin, kRay.tMax, &tEnter));
    DdaState state = ddaSetup(grid, kRay, tEnter, kRay.tMax);
    std::vector<GridCell> cells = {state.cell};
    while (ddaStep(state, grid.resolution)) cells.push_back(state.cell);
    std::vector<uint32_t> nodes = viewer::resolveTraceNodes(g.view, g.trace, kRay, cells, grid.resolution);
    size_t step = 0;
    for (size_t i = 0; i < g.trace.ops.size(); ++i) {
        if (g.trace.ops[i].kind != TraceOpKind::CellStep) continue;
        REQUIRE(nodes[i] != kUnresolved);
        CHECK(nodes[i] == 1 + grid.cellIndex(cells[step++]));
    }
    CHECK(step > 1);

    Traced k("kdtree", kRay);
    std::vector<uint32_t> kdNodes = viewer::resolveTraceNodes(k.view, k.trace, kRay, {}, {0, 0, 0});
    bool sawPlane = false;
    for (size_t i = 0; i < k.trace.ops.size(); ++i) {
        const TraceOp& op = k.trace.ops[i];
        if (op.kind == TraceOpKind::PlaneStep && kdNodes[i] != kUnresolved) {
            sawPlane = true;
            CHECK(k.view.nodes[kdNodes[i]].childCount == 2);  // a plane step is at an interior node
        }
        if (op.kind == TraceOpKind::PrimitiveTest || op.kind == TraceOpKind::MailboxRepeat) {
            REQUIRE(kdNodes[i] != kUnresolved);
            const StructureNode& leaf = k.view.nodes[kdNodes[i]];
            auto first = k.view.primIndices.begin() + leaf.firstPrim;
            CHECK(std::find(first, first + leaf.primCount, op.index) != first + leaf.primCount);
        }
    }
    CHECK(sawPlane);
}

TEST_CASE("two traces part at their first different step") {
    Traced t("bvh", kRay);
    CHECK(viewer::firstDifference(t.trace, t.trace) == -1);
    TraversalTrace other = t.trace;
    other.ops[3].hit ^= 1;
    CHECK(viewer::firstDifference(t.trace, other) == 3);
    other = t.trace;
    other.boxes[other.ops[0].index].upper.x += 1.0f;
    CHECK(viewer::firstDifference(t.trace, other) == 0);
    other = t.trace;
    other.ops.pop_back();
    CHECK(viewer::firstDifference(t.trace, other) == static_cast<int64_t>(other.ops.size()));
}

TEST_CASE("a page carries whole top levels, the nodes a trace visits and their ancestors; bad links are dropped") {
    Traced t("bvh-median", kRay);
    viewer::NodeSelection all = viewer::selectNodes(t.view, DrawingStyle::Levels, 1 << 20, {});
    CHECK(all.nodes.size() == t.view.nodes.size());
    viewer::NodeSelection top = viewer::selectNodes(t.view, DrawingStyle::Levels, 3, {});
    CHECK(top.nodes.size() == 3);  // the root and its two children
    CHECK(top.completeDepth == 1);
    uint32_t deep = all.nodes.back();
    viewer::NodeSelection wanted = viewer::selectNodes(t.view, DrawingStyle::Levels, 3, {deep});
    CHECK(wanted.shippedOf[deep] != viewer::kNoNode);
    for (size_t i = 0; i < wanted.nodes.size(); ++i)
        if (wanted.parent[i] != viewer::kNoNode) CHECK(wanted.parent[i] < i);  // parents first

    StructureView broken = t.view;
    broken.children[broken.nodes[0].firstChild] = 0;            // the root as its own child
    broken.children[broken.nodes[0].firstChild + 1] = 1u << 30;  // out of range
    viewer::NodeSelection s = viewer::selectNodes(broken, DrawingStyle::Levels, 1 << 20, {5, 1u << 31});
    CHECK(s.malformed == 2);
    CHECK(s.nodes.size() == 1);  // nothing else is reachable from the root
    broken.nodes[0].childCount = 1u << 31;  // a list that runs past the children
    CHECK(viewer::selectNodes(broken, DrawingStyle::Levels, 1 << 20, {}).malformed == 1);
}

TEST_CASE("split planes are drawn inside their cells") {
    Traced k("kdtree", kRay);
    StructureDrawing d = drawStructure("kdtree", k.view);
    CHECK(d.style == DrawingStyle::Planes);
    REQUIRE(!d.planes.empty());
    for (const DrawnPlane& p : d.planes) {
        const StructureNode& node = k.view.nodes[p.node];
        const StructurePlane& plane = k.view.planes[p.node];
        CHECK(p.polygon.size() == 4);  // an axis-aligned cut of a box is a rectangle
        for (const Vec3& c : p.polygon) {
            CHECK(glm::dot(DVec3(c), plane.normal) == doctest::Approx(plane.offset).epsilon(1e-5));
            for (int a = 0; a < 3; ++a) {
                CHECK(c[a] >= node.bounds.lower[a] - 1e-4f);
                CHECK(c[a] <= node.bounds.upper[a] + 1e-4f);
            }
        }
    }
    Traced b("bsp", kRay);
    StructureDrawing bsp = drawStructure("bsp", b.view);
    CHECK(!bsp.boxesMeaningful);
    REQUIRE(!bsp.planes.empty());
    for (const DrawnPlane& p : bsp.planes) CHECK(p.polygon.size() >= 3);
    CHECK(drawStructure("bvh-median", k.view).valueName == "SAH share");
    CHECK(drawStructure("grid:C=9", k.view).style == DrawingStyle::Cells);
    CHECK_THROWS_AS(drawStructure("nonsense", k.view), Error);
}

TEST_CASE("writeCaseViewer: a new, empty or viewer folder only, and student text never as markup") {
    fs::path root = test::outputDir("viewer");
    Traced t("bvh", kRay);
    viewer::CaseView view;
    const std::string hostile = "</script><script>window.__pwned=1</script><img src=x onerror=\"window.__pwned=2\"> & \"quotes\"";
    view.title = hostile;
    view.notes = {hostile, std::string("bytes \x1b[31m\xff\xfe end")};
    view.scene = &t.scene;
    view.acceleratorName = "bvh";
    view.draw = drawBvh;
    view.structure = t.view;
    viewer::RayCase& c = view.rays.emplace_back();
    c.ray = kRay;
    c.label = hostile;
    c.student = viewer::RayAnswer::closest(t.hit.prim, t.hit.t);
    c.studentTrace = t.trace;

    fs::path dir = root / "case";
    fs::remove_all(dir);
    viewer::writeCaseViewer(dir, view);
    std::string html = readFile(dir / "index.html");
    CHECK(fs::is_regular_file(dir / viewer::kViewerMarker));
    // The page's own five script elements close, and nothing else does: the hostile text is in
    // the JSON element with its '<' escaped.
    CHECK(occurrences(html, "</script>") == 5);
    CHECK(html.find("window.__pwned") != std::string::npos);
    CHECK(html.find("<img src=x") == std::string::npos);
    CHECK(html.find("\\u003c/script\\u003e\\u003cscript\\u003ewindow.__pwned=1") != std::string::npos);
    CHECK(html.find("\x1b") == std::string::npos);
    CHECK(html.find("script-src 'sha256-") != std::string::npos);

    // A viewer written before is replaced; an empty folder is filled.
    CHECK_NOTHROW(viewer::writeCaseViewer(dir, view));
    fs::path empty = root / "empty";
    fs::remove_all(empty);
    fs::create_directories(empty);
    CHECK_NOTHROW(viewer::writeCaseViewer(empty, view));

    // A folder with other files is left alone, and so is a file.
    fs::path other = root / "other";
    fs::remove_all(other);
    fs::create_directories(other);
    std::ofstream(other / "notes.txt") << "mine";
    CHECK_THROWS_WITH_AS(viewer::writeCaseViewer(other, view), doctest::Contains("is not a viewer folder"), Error);
    CHECK(readFile(other / "notes.txt") == "mine");
    CHECK(!fs::exists(other / "index.html"));
    fs::path file = root / "a-file";
    std::ofstream(file) << "x";
    CHECK_THROWS_AS(viewer::writeCaseViewer(file, view), Error);
    CHECK_THROWS_AS(viewer::writeCaseViewer(root / "missing-parent" / "case", view), Error);
    // No scratch folder is left behind.
    for (const auto& entry : fs::directory_iterator(root)) CHECK(entry.path().filename().string().find(".writing-") == std::string::npos);
}

}  // namespace rtlab
