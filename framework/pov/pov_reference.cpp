#include "framework/pov/pov_reference.h"

#include "framework/core/error.h"
#include "framework/pov/pov_exporter.h"
#include "framework/pov/povray_process.h"

#include <cstdio>
#include <fstream>

namespace rtlab {
namespace fs = std::filesystem;

namespace {

// One render thread (+WT1): POV-Ray tries the last occluder it met first (a per-thread shadow
// cache), so with several threads a shadow ray that grazes within POV-Ray's tolerances can
// come out differently from run to run (measured: one pixel of smooth-mesh flipped between
// runs); single-threaded renders are reproducible, and at 320x240 not slower (parsing and
// start-up dominate).
std::vector<std::string> povReferenceArguments(int width, int height) {
    return {"+W" + std::to_string(width), "+H" + std::to_string(height), "-A", "-D", "+FN16",
            "File_Gamma=1.0", "+WT1"};
}

}  // namespace

std::string povReferenceSettings(int width, int height) {
    std::string settings;
    for (const std::string& argument : povReferenceArguments(width, height))
        settings += (settings.empty() ? "" : " ") + argument;
    return settings;
}

namespace {

// Exports the scene into work and renders it there as image.png, with the log in work/povray.log.
void renderInto(TemporaryDirectory& work, const Scene& scene, const Camera& camera, int width, int height) {
    if (width <= 0 || height <= 0)
        throw Error("POV-Ray reference: image size " + std::to_string(width) + "x" +
                    std::to_string(height) + " is not positive");
    {
        std::ofstream pov(work.path() / "scene.pov");
        pov << exportPovScene(scene, camera, width, height);
        if (!pov) throw Error((work.path() / "scene.pov").string() + ": cannot write the POV-Ray scene");
    }
    std::vector<std::string> arguments{"-Iscene.pov"};
    for (const std::string& argument : povReferenceArguments(width, height)) arguments.push_back(argument);
    arguments.push_back("-Oimage.png");
    runPovrayOrThrow(arguments, work, "rendering " + scene.sourcePath);
}

}  // namespace

void renderPovReference(const Scene& scene, const Camera& camera, int width, int height,
                        const fs::path& outputPng) {
    TemporaryDirectory work("rtlab-povray");
    renderInto(work, scene, camera, width, height);
    std::error_code error;
    fs::copy_file(work.path() / "image.png", outputPng, fs::copy_options::overwrite_existing, error);
    if (error)
        throw Error(outputPng.string() + ": cannot write the POV-Ray reference: " + error.message());
}

double timePovReference(const Scene& scene, const Camera& camera, int width, int height) {
    TemporaryDirectory work("rtlab-povray-time");
    renderInto(work, scene, camera, width, height);
    // POV-Ray 3.7's statistics: "  Trace Time:       0 hours  0 minutes  0 seconds (0.253 seconds)".
    std::ifstream log(work.path() / "povray.log");
    std::string line;
    while (std::getline(log, line)) {
        if (line.find("Trace Time:") == std::string::npos) continue;
        size_t open = line.rfind('(');
        double seconds = 0.0;
        if (open != std::string::npos && std::sscanf(line.c_str() + open + 1, "%lf", &seconds) == 1) return seconds;
    }
    work.keep();
    throw Error((work.path() / "povray.log").string() + ": POV-Ray reported no Trace Time");
}

}  // namespace rtlab
