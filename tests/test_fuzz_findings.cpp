// Inputs that broke a parser of outside input (tests/data/fuzz-findings/README.md says how):
// each must now end in one rtlab::Error, one line starting with the file's path and naming the
// problem.
#include "framework/core/error.h"
#include "framework/external/reference_manifest.h"
#include "framework/scene/gltf_loader.h"
#include "grader/engine/rubric.h"

#include <doctest/doctest.h>

#include <functional>
#include <string>

namespace {

std::string finding(const std::string& name) {
    return std::string(RTLAB_SOURCE_DIR) + "/tests/data/fuzz-findings/" + name;
}

void checkRejected(const std::function<void(const std::string&)>& parse, const std::string& name,
                   const std::string& problem) {
    std::string path = finding(name);
    CAPTURE(path);
    try {
        parse(path);
        FAIL("parsed without an error");
    } catch (const rtlab::Error& e) {
        std::string message = e.what();
        CAPTURE(message);
        CHECK(message.rfind(path + ": ", 0) == 0);
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.find(problem) != std::string::npos);
    }
}

void loadRubric(const std::string& path) { rtlab::grader::Rubric::load(path); }
void loadManifest(const std::string& path) { rtlab::ReferenceManifest::load(path); }
void loadScene(const std::string& path) { rtlab::loadGltf(path); }

}  // namespace

TEST_CASE("fuzz findings: the rubric parser") {
    checkRejected(loadRubric, "rubric-newline-in-pattern.json", R"(rule "a\nb" has visibility "x")");
    checkRejected(loadRubric, "rubric-precision-wraps-to-2.json", R"("precision" must be a whole number)");
}

TEST_CASE("fuzz findings: the reference manifest parser") {
    checkRejected(loadManifest, "manifest-format-1e300.json", "manifest format must be a whole number from 0 to 2147483647");
    checkRejected(loadManifest, "manifest-width-1e10.json", R"(reference "a\nb": width must be a whole number)");
    checkRejected(loadManifest, "manifest-width-wraps-to-1.json", R"(reference "a": width must be a whole number)");
}

TEST_CASE("fuzz findings: the glTF loader") {
    // Its header declares 0 bytes: the chunk checks subtracted from that and read past the file.
    checkRejected(loadScene, "glb-length-below-header.glb", "GLB header declares 0 bytes, the file has 87");
}
