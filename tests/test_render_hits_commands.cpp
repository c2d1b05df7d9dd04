// `rtlab render` and `rtlab hits` end to end on a committed glTF scene: files written, the CSV
// contract, the accelerator agreeing with the oracle, and one-line errors with exit code 1.
#include "framework/core/error.h"
#include "framework/core/ray_file.h"
#include "framework/render/image_io.h"
#include "tests/cli_runner.h"
#include "tests/output_dirs.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

using namespace rtlab;
namespace fs = std::filesystem;

namespace {

const std::string kScene = std::string(RTLAB_SOURCE_DIR) + "/scenes/spheres.gltf";

fs::path outputDir() { return test::outputDir("commands"); }

std::vector<std::vector<std::string>> readCsv(const fs::path& path, std::string* header) {
    std::ifstream in(path);
    std::getline(in, *header);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> fields;
        std::stringstream stream(line);
        for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
        rows.push_back(fields);
    }
    return rows;
}

// Rays from in front of the scene towards a grid of targets, plus a ray cut short by tMax.
fs::path writeRays() {
    std::vector<Ray> rays;
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 25; ++j) {
            Ray ray;
            ray.origin = {0.1f, 1.2f, 6.0f};
            ray.direction = Vec3(-3.0f + 0.15f * i, 0.06f * j, -3.0f) - ray.origin;
            rays.push_back(ray);
        }
    }
    Ray shortRay = rays[500];
    shortRay.tMax = 0.01f;
    rays.push_back(shortRay);
    fs::path path = outputDir() / "rays.txt";
    writeRayFile(path.string(), rays);
    CHECK(readRayFile(path.string()).size() == rays.size());
    return path;
}

}  // namespace

TEST_CASE("rtlab hits: CSV contract, and brute force and BVH agree with the oracle") {
    fs::path rays = writeRays();
    fs::path oracleCsv = outputDir() / "oracle.csv";
    REQUIRE(test::runCliStatus({"hits", kScene, "--rays", rays.string(), "--accel", "oracle", "-o", oracleCsv.string()}) == 0);
    std::string header;
    auto oracle = readCsv(oracleCsv, &header);
    CHECK(header == "ray,hit,t,prim,px,py,pz,nx,ny,nz");
    REQUIRE(oracle.size() == 1001);
    int hits = 0;
    for (size_t i = 0; i < oracle.size(); ++i) {
        REQUIRE(oracle[i].size() == 10);
        CHECK(oracle[i][0] == std::to_string(i));
        if (oracle[i][1] == "1") {
            ++hits;
            double nx = std::stod(oracle[i][7]), ny = std::stod(oracle[i][8]), nz = std::stod(oracle[i][9]);
            CHECK(std::sqrt(nx * nx + ny * ny + nz * nz) == doctest::Approx(1.0).epsilon(1e-12));
        }
    }
    CHECK(hits > 100);
    CHECK(oracle[1000][1] == "0");  // cut short by tMax
    CHECK(oracle[1000][2] == "inf");

    for (const char* accel : {"brute", "bvh-buckets"}) {
        CAPTURE(accel);
        fs::path csv = outputDir() / (std::string(accel) + ".csv");
        REQUIRE(test::runCliStatus({"hits", kScene, "--rays", rays.string(), "--accel", accel, "-o", csv.string()}) == 0);
        auto rows = readCsv(csv, &header);
        REQUIRE(rows.size() == oracle.size());
        for (size_t i = 0; i < rows.size(); ++i) {
            CHECK(rows[i][1] == oracle[i][1]);
            if (rows[i][1] != "1" || oracle[i][1] != "1") continue;
            CHECK(rows[i][3] == oracle[i][3]);
            CHECK(std::stod(rows[i][2]) == doctest::Approx(std::stod(oracle[i][2])).epsilon(1e-5));
        }
    }
}

TEST_CASE("rtlab hits: a malformed ray file names its line") {
    fs::path rays = outputDir() / "bad-rays.txt";
    std::ofstream(rays) << "# comment\n\n0 0 0 0 0 -1\n0 0 0 0 0\n";
    fs::path csv = outputDir() / "bad.csv";
    CHECK(test::runCliStatus({"hits", kScene, "--rays", rays.string(), "-o", csv.string()}) == 1);
    CHECK_THROWS_WITH_AS(readRayFile(rays.string()), doctest::Contains("bad-rays.txt:4: expected 6 or 8 numbers"),
                         Error);
    std::ofstream(rays) << "0 0 0 0 0 -1 0 zz\n";
    CHECK_THROWS_WITH_AS(readRayFile(rays.string()), doctest::Contains("bad-rays.txt:1: 'zz' is not a float"), Error);
}

TEST_CASE("rtlab render: image and AOV files, sizes from the camera's aspect") {
    fs::path out = outputDir() / "spheres.png";
    fs::path aovDir = outputDir() / "aovs";
    fs::create_directories(aovDir);
    REQUIRE(test::runCliStatus({"render", kScene, "-o", out.string(), "--linear16", "--width", "64", "--threads", "3", "--aov", "normal",
                   "--aov", "cost", "--aov", "depth", "--aov-dir", aovDir.string()}) == 0);
    Image image = readImage(out.string());
    CHECK(image.width == 64);
    CHECK(image.height == 48);  // the scene's camera has aspect 4:3
    double sum = 0.0;
    for (float v : image.pixels) sum += v;
    CHECK(sum > 0.0);
    for (const char* aov : {"normal", "cost", "depth"})
        CHECK(fs::exists(aovDir / ("spheres." + std::string(aov) + ".png")));

    fs::path exr = outputDir() / "spheres.exr";
    REQUIRE(test::runCliStatus({"render", kScene, "-o", exr.string(), "--width", "64", "--accel", "brute"}) == 0);
    Image linear = readImage(exr.string());
    // The PNG holds the same radiance, quantised.
    for (size_t i = 0; i < image.pixels.size(); ++i)
        CHECK(std::lround(image.pixels[i] * 65535.0f) == encodeLinear16(linear.pixels[i]));
}

TEST_CASE("rtlab render: bad outputs fail before rendering, with exit code 1") {
    CHECK(test::runCliStatus({"render", kScene, "-o", (outputDir() / "missing" / "x.png").string()}) == 1);
    CHECK(test::runCliStatus({"render", kScene, "-o", (outputDir() / "x.tif").string()}) == 1);
    CHECK(test::runCliStatus({"render", kScene, "-o", (outputDir() / "x.png").string(), "--linear16", "--exposure", "2"}) == 1);
    CHECK(test::runCliStatus({"render", kScene, "-o", (outputDir() / "x.exr").string(), "--exposure", "2"}) == 1);
    CHECK(test::runCliStatus({"render", kScene, "-o", (outputDir() / "x.png").string(), "--accel", "kd-magic"}) == 1);
    CHECK(test::runCliStatus({"render", kScene, "-o", (outputDir() / "x.png").string(), "--aov", "albedo"}) == 2);
    CHECK_FALSE(fs::exists(outputDir() / "x.png"));
}
