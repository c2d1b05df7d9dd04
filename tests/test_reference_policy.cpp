// What rtlab refs decides, apart from what it prints (framework/external/reference_policy.h):
// each reason to render a reference again, and each reason a committed one is not current.
#include "framework/core/sha256.h"
#include "framework/external/reference_policy.h"
#include "framework/external/temporary_directory.h"

#include <doctest/doctest.h>

#include <fstream>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// A repository with one scene and its committed reference, described by the manifest's entry.
struct Repository {
    TemporaryDirectory work{"rtlab-test-policy"};
    ReferenceFolder folder;
    fs::path scene;
    ReferenceManifest manifest;
    ReferenceEntry entry;

    Repository() {
        folder.root = work.path();
        folder.refsDir = work.path() / "scenes" / "refs";
        folder.manifestPath = folder.refsDir / "manifest.json";
        fs::create_directories(folder.refsDir);
        scene = work.path() / "scenes" / "box.gltf";
        write(scene, R"({"asset": {"version": "2.0"}})");
        write(folder.refsDir / "box.png", "pixels");
        entry.name = "box";
        entry.scene = "scenes/box.gltf";
        entry.inputs = hashSceneInputs(scene, folder.root);
        entry.exporter = "exporter 1";
        entry.renderer = "POV-Ray 3.7";
        entry.width = 320;
        entry.height = 240;
        entry.settings = "+A0.3";
        entry.image = "box.png";
        entry.imageSha256 = sha256OfFile((folder.refsDir / "box.png").string());
        manifest.entries["box"] = entry;
    }
};

}  // namespace

TEST_CASE("reference policy: a reference is rendered again exactly when its recipe or image changed") {
    Repository repo;
    ReferenceEntry wanted = repo.entry;
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", false) == "");
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", true) == "forced");
    wanted.name = "other";
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", false) == "new");
    wanted = repo.entry;
    wanted.inputs.begin()->second = "0";
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", false) == "scene changed");
    wanted = repo.entry;
    wanted.exporter = "exporter 2";
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", false) == "exporter changed");
    wanted = repo.entry;
    wanted.renderer = "POV-Ray 3.8";
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", false) == "POV-Ray version changed");
    wanted = repo.entry;
    wanted.width = 640;
    CHECK(whyRender(wanted, repo.manifest, repo.folder, "POV-Ray", false) == "settings changed");
    write(repo.folder.refsDir / "box.png", "other pixels");
    CHECK(whyRender(repo.entry, repo.manifest, repo.folder, "POV-Ray", false) == "image modified");
    fs::remove(repo.folder.refsDir / "box.png");
    CHECK(whyRender(repo.entry, repo.manifest, repo.folder, "POV-Ray", false) == "image missing");
}

TEST_CASE("reference policy: a committed reference is current, or says why it is not") {
    Repository repo;
    CHECK(staleReference("box", repo.scene, repo.manifest, repo.folder) == "");
    CHECK(staleReference("sphere", repo.scene, repo.manifest, repo.folder) == "no reference in " + repo.folder.manifestPath.string());
    write(repo.scene, R"({"asset": {"version": "2.0"}, "scene": 0})");
    CHECK(staleReference("box", repo.scene, repo.manifest, repo.folder) == "scenes/box.gltf changed since its reference was rendered");
    repo.manifest.entries["box"].inputs = hashSceneInputs(repo.scene, repo.folder.root);
    fs::remove(repo.folder.refsDir / "box.png");
    CHECK(staleReference("box", repo.scene, repo.manifest, repo.folder) == (repo.folder.refsDir / "box.png").string() + " is missing");
}
