// Images: every scene in scenes/ (and every referenced model, such as the bunny) rendered with
// the student's structure (a1: the median BVH; a3: the grid; always a0's intersections) and
// compared with its POV-Ray reference in scenes/refs/. A scene without a reference, or whose reference is
// older than the scene, scores 0 with that reason, never a silent pass.
#include "framework/core/error.h"
#include "framework/core/sha256.h"
#include "framework/verification/image_compare.h"
#include "framework/render/image_io.h"
#include "framework/scene/gltf_loader.h"
#include "grader/kit/image_tests.h"
#include "grader/wire/scene_codec.h"
#include "grader/wire/task_inputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

namespace rtlab::grader {
namespace {

namespace fs = std::filesystem;

// A render passes when at most this share of its pixels differ from the reference by more
// than kImageThresholdCodes 16-bit codes in some channel.
constexpr double kImageThresholdCodes = 2.0;
constexpr double kImageMaxShareOver = 0.005;

std::string percent(double share) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f%%", 100.0 * share);
    return buffer;
}

struct ImageJob {
    std::string name;
    Scene scene;
    uint32_t camera = 0;  // index into scene.cameras
    Image reference;
    std::string referencePath;
};

uint32_t cameraIndex(const Scene& scene, const std::string& name) {
    const Camera& camera = scene.camera(name);  // throws with the list of names when there is none
    return static_cast<uint32_t>(&camera - scene.cameras.data());
}

TestGroup renderGroup(const ImageConfig& config, std::shared_ptr<ImageJob> job, const std::string& workDir) {
    TestGroup group;
    group.assignment = config.assignment;
    group.title = "render " + job->name + " with " + config.accelerator;
    worker::RenderRequest request{job->camera, job->reference.width, job->reference.height, 2, {}};
    if (config.accelerator.size() >= sizeof request.accelerator) throw Error("accelerator name too long: " + config.accelerator);
    std::copy(config.accelerator.begin(), config.accelerator.end(), request.accelerator);
    ByteWriter input;
    writeScene(job->scene, input);
    input.put(request);
    group.phases = {noSetUp(), makePhase(config.stub, worker::kTaskRender, std::move(input), config.entry)};
    group.score = [config, job, workDir](const SandboxRun& run, std::vector<TestResult>& results) {
        TestResult result = makeResult(config.assignment, config.assignment + "/images/" + job->name);
        if (!failedPhaseResult(run.phases[1], result)) {
            try {
                ByteReader in(run.phases[1].data);
                Image render;
                render.width = in.get<int32_t>();
                render.height = in.get<int32_t>();
                render.channels = in.get<int32_t>();
                if (render.width != job->reference.width || render.height != job->reference.height || render.channels != 3)
                    throw WireError("the render has the wrong size");
                std::vector<float> pixels = in.getVector<float>(size_t(render.width) * render.height * 3);
                render.pixels.assign(pixels.begin(), pixels.end());
                if (render.pixels.size() != size_t(render.width) * render.height * 3) throw WireError("the render is incomplete");
                ImageComparison c = compareImages(render, job->reference, kImageThresholdCodes);
                fs::create_directories(workDir);
                std::string base = workDir + "/" + job->name;
                writeImage(base + "-render.png", render, ImageWriteOptions{true, 0.0f});
                writeImage(base + "-reference.png", job->reference, ImageWriteOptions{true, 0.0f});
                writeErrorHeatMap(render, job->reference, base + kHeatMapFileSuffix);
                result.images = {{"your render", fs::absolute(base + "-render.png").string()},
                                 {"POV-Ray reference", fs::absolute(base + "-reference.png").string()},
                                 // The HTML report draws the colours' legend under the images once.
                                 {"difference in 16-bit codes", fs::absolute(base + kHeatMapFileSuffix).string()}};
                std::string summary = percent(c.shareOverThreshold()) + " of pixels off by more than " +
                                      std::to_string(int(kImageThresholdCodes)) + " codes (allowed " + percent(kImageMaxShareOver) +
                                      "); mean error " + std::to_string(c.meanCodes()) + " codes, max " + std::to_string(c.maxCodes()) +
                                      " at (" + std::to_string(c.maxX) + ", " + std::to_string(c.maxY) + ")";
                result.details.push_back(summary);
                result.details.push_back("reference: " + job->referencePath);
                bool passed = c.shareOverThreshold() <= kImageMaxShareOver;
                result.status = passed ? TestStatus::Passed : TestStatus::Failed;
                result.fraction = passed ? 1.0 : 0.0;
                result.reason = passed ? "" : summary;
                if (!passed) {
                    // The viewer opens the render at its worst pixel, with that pixel's camera ray.
                    FailedCase failed;
                    failed.title = result.name + ": the worst pixel";
                    failed.notes = {summary};
                    failed.scene = std::shared_ptr<const Scene>(job, &job->scene);
                    failed.image = CaseImage{result.images[0].path, result.images[1].path, result.images[2].path, job->camera,
                                             render.width, render.height, std::array<int, 2>{c.maxX, c.maxY}, summary};
                    addFailedCase(result, std::move(failed));
                }
                result.needsFollowedStructure = true;
            } catch (const std::exception& e) {
                result.status = TestStatus::Failed;
                result.reason = e.what();
            }
        }
        results.push_back(std::move(result));
    };
    return group;
}

// A test that cannot run (no reference, scene does not load): no phases, so no child; 0 points
// and the reason.
TestGroup unavailableGroup(const std::string& assignment, const std::string& name, const std::string& reason) {
    TestGroup group;
    group.assignment = assignment;
    group.title = "render " + name;
    group.score = [assignment, name, reason](const SandboxRun&, std::vector<TestResult>& results) {
        TestResult result = makeResult(assignment, assignment + "/images/" + name);
        result.reason = reason;
        results.push_back(std::move(result));
    };
    return group;
}

}  // namespace

std::vector<TestGroup> imageGroups(GradingContext& context, const ImageConfig& config) {
    // The references and what they were made from (scenes/refs/manifest.json, written by
    // rtlab refs); every scene in scenes/ is graded, with or without a reference.
    const fs::path root(context.sourceDir), refs = root / "scenes" / "refs";
    nlohmann::json manifest = nlohmann::json::object();
    if (fs::exists(refs / "manifest.json")) {
        try {
            manifest = nlohmann::json::parse(std::ifstream(refs / "manifest.json")).at("references");
        } catch (const nlohmann::json::exception&) {
            manifest = nlohmann::json::object();
        }
    }
    std::map<std::string, fs::path> scenes;
    if (fs::is_directory(root / "scenes"))
        for (const auto& entry : fs::directory_iterator(root / "scenes"))
            if (entry.path().extension() == ".gltf" || entry.path().extension() == ".glb") scenes[entry.path().stem().string()] = entry.path();
    // Referenced models outside scenes/ (the bunny) are looked up in the models folder.
    for (const auto& [name, entry] : manifest.items()) {
        fs::path scene = entry.value("scene", "");
        scenes.try_emplace(name, fs::exists(root / scene) ? root / scene : fs::path(context.modelsDir) / scene.filename());
    }

    std::vector<TestGroup> groups;
    for (const auto& [name, file] : scenes) {
        if (!manifest.contains(name) || !fs::exists(refs / manifest[name].value("image", ""))) {
            groups.push_back(unavailableGroup(config.assignment, name, "no reference: scenes/refs has none for " + file.filename().string() +
                                                        " (an instructor runs rtlab refs)"));
            continue;
        }
        const nlohmann::json& entry = manifest[name];
        auto job = std::make_shared<ImageJob>();
        job->name = name;
        job->referencePath = (refs / entry.value("image", "")).string();
        try {
            if (!fs::exists(file)) throw Error(file.string() + " does not exist (run make models)");
            const nlohmann::json inputs = entry.value("inputs", nlohmann::json::object());
            for (const auto& [input, digest] : inputs.items())
                if (input == entry.value("scene", "") && sha256OfFile(file.string()) != digest.get<std::string>())
                    throw Error("stale reference: " + file.string() + " changed after " + job->referencePath +
                                " was rendered (an instructor runs rtlab refs)");
            job->scene = loadGltf(file.string());
            job->camera = cameraIndex(job->scene, entry.value("camera", "camera"));
            job->reference = readImage(job->referencePath);
        } catch (const std::exception& e) {
            groups.push_back(unavailableGroup(config.assignment, name, e.what()));
            continue;
        }
        groups.push_back(renderGroup(config, job, context.workDir + "/images/" + config.assignment));
    }
    return groups;
}

}  // namespace rtlab::grader
