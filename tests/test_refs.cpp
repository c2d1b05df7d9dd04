// `rtlab refs` on a scratch copy of a committed scene: renders once, skips what is up to date,
// re-renders what changed, --check catches a modified reference, --hits agrees with the oracle.
// Runs live POV-Ray.
#include "framework/external/reference_manifest.h"
#include "framework/render/image_io.h"
#include "tests/cli_runner.h"
#include "tests/output_dirs.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <vector>

using namespace rtlab;
using test::CliResult;
using test::runCli;
namespace fs = std::filesystem;

TEST_CASE("rtlab refs: render, skip when up to date, re-render and --check when changed") {
    fs::path scenes = test::scratchScenes("refs", {"light-behind.gltf"});
    std::vector<std::string> size{"--scenes", scenes.string(), "--width", "64", "--height", "48"};
    auto with = [&size](std::vector<std::string> head) {
        head.insert(head.end(), size.begin(), size.end());
        return head;
    };
    fs::path image = scenes / "refs" / "light-behind.png";

    CliResult first = runCli(with({"refs"}));
    REQUIRE(first.status == 0);
    CHECK(first.out.find("rendered 64x48") != std::string::npos);
    CHECK(first.out.find("(new)") != std::string::npos);
    ReferenceManifest manifest = ReferenceManifest::load(scenes / "refs" / "manifest.json");
    REQUIRE(manifest.entries.count("light-behind") == 1);
    const ReferenceEntry& entry = manifest.entries["light-behind"];
    CHECK(entry.scene == "scenes/light-behind.gltf");
    CHECK(entry.inputs.size() == 1);
    CHECK(entry.settings == "+W64 +H48 -A -D +FN16 File_Gamma=1.0 +WT1");
    CHECK(entry.renderer.rfind("POV-Ray 3.7", 0) == 0);
    CHECK(readImage(image.string()).width == 64);

    CliResult second = runCli(with({"refs"}));
    CHECK(second.status == 0);
    CHECK(second.out.find("up to date") != std::string::npos);
    CHECK(second.out.find("rendered") == std::string::npos);

    CHECK(runCli(with({"refs", "--check"})).status == 0);

    // A tampered reference: --check fails, and refs re-renders it.
    Image tampered = readImage(image.string());
    tampered.at(10, 10, 0) += 0.25f;
    writeImage(image.string(), tampered);
    CliResult check = runCli(with({"refs", "--check"}));
    CHECK(check.status != 0);
    CHECK(check.out.find("FAIL: differs") != std::string::npos);
    CliResult repair = runCli(with({"refs"}));
    CHECK(repair.out.find("(image modified)") != std::string::npos);
    CHECK(runCli(with({"refs", "--check"})).status == 0);

    // Another size is another recipe.
    CliResult resized = runCli({"refs", "--scenes", scenes.string(), "--width", "32", "--height", "24"});
    CHECK(resized.out.find("(settings changed)") != std::string::npos);
}

TEST_CASE("rtlab refs --hits: POV-Ray's trace() agrees with the oracle on a committed scene") {
    fs::path scenes = test::scratchScenes("refs", {"light-behind.gltf"});
    CliResult hits = runCli({"refs", "--hits", "--rays", "300", "--scenes", scenes.string()});
    CHECK(hits.status == 0);
    CHECK(hits.out.find("agree: 300 rays") != std::string::npos);
}

TEST_CASE("rtlab refs: a missing scenes folder is one clear error") {
    CHECK(runCli({"refs", "--scenes", "/nonexistent/scenes"}).status != 0);
}
