// The statistical comparison of replicated renders with a near-exact reference
// (framework/verification/statistical_comparison.h) on images whose statistics are known by hand, and
// the edge pixels it leaves out (framework/verification/edge_pixels.h) on a scene whose edge is
// placed inside one pixel column.
#include "framework/accel/accelerator.h"
#include "framework/core/error.h"
#include "framework/verification/edge_pixels.h"
#include "framework/verification/replicates.h"
#include "framework/verification/statistical_comparison.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace rtlab;

namespace {

constexpr int kWidth = 8, kHeight = 6;

Image filled(float value) {
    Image image(kWidth, kHeight, 3);
    std::fill(image.pixels.begin(), image.pixels.end(), value);
    return image;
}

// Four replicates whose every value is 1.1, 0.9, 1.1, 0.9: mean 1, sample variance
// 4 (0.1)^2 / 3 = 0.01333, standard error of a pixel sqrt(0.01333 / 4) = 0.05774; a region of
// 2 x 2 pixels (the 4 x 3 regions of an 8 x 6 image) has the standard error
// sqrt(4 x 0.01333 / 4) / 4 = 0.02887.
ReplicateStatistics alternating() {
    ReplicateStatistics stats;
    for (int k = 0; k < 4; ++k) stats.add(filled(k % 2 ? 0.9f : 1.1f));
    return stats;
}

void setPixel(Image& image, int x, int y, float value) {
    for (int c = 0; c < 3; ++c) image.at(x, y, c) = value;
}

}  // namespace

TEST_CASE("statistical comparison: the replicates' means and variances are Welford's") {
    ReplicateStatistics stats = alternating();
    CHECK(stats.replicates() == 4);
    CHECK(stats.mean(0) == doctest::Approx(1.0).epsilon(1e-7));
    CHECK(stats.variance(0) == doctest::Approx(0.04 / 3.0).epsilon(1e-6));
    CHECK(stats.meanImage().at(3, 2, 1) == doctest::Approx(1.0f));
    CHECK_THROWS_AS(stats.add(Image(4, 4, 3)), Error);
}

TEST_CASE("statistical comparison: a reference equal to our mean passes; one pixel off by 0.5 fails both families") {
    ReplicateStatistics ours = alternating();
    StatisticalComparison same = compareStatistically(ours, filled(1.0f));
    CHECK(same.passes());
    CHECK(same.regions.size() == 4 * 3 * 3);
    CHECK(same.pixelValues == kWidth * kHeight * 3);
    CHECK(same.pixelFailures == 0);
    CHECK(same.regions[0].pixels == 4);
    CHECK(same.regions[0].standardError == doctest::Approx(0.028868).epsilon(1e-4));
    // Sidak: 36 region tests at family level 0.01 each test at 1 - 0.99^(1/36) = 2.792e-4.
    CHECK(same.regionLevel == doctest::Approx(2.792e-4).epsilon(1e-3));

    Image reference = filled(1.0f);
    setPixel(reference, 5, 4, 1.5f);
    StatisticalComparison off = compareStatistically(ours, reference);
    // The pixel: z = -0.5 / sqrt(0.05774^2 + (2.5e-3 x 1.5)^2) = -8.64, far beyond the Sidak
    // threshold for 144 values (level 6.98e-5, |z| 3.97).
    CHECK(off.pixelFailures == 3);
    CHECK(off.worstPixelZ == doctest::Approx(-8.64).epsilon(1e-3));
    CHECK(off.worstX == 5);
    CHECK(off.worstY == 4);
    // Its region (x 4..5, y 4..5): reference mean 1.125, z = -0.125 / sqrt(0.02887^2 + (5e-4 x
    // 1.125)^2) = -4.33 beyond the regions' |z| 3.63.
    CHECK(off.regionFailures() == 3);
    CHECK_FALSE(off.passes());

    // Left out (an edge pixel), it takes part in neither family.
    std::vector<uint8_t> leftOut(kWidth * kHeight, 0);
    leftOut[4 * kWidth + 5] = 1;
    StatisticalComparison without = compareStatistically(ours, reference, leftOut);
    CHECK(without.passes());
    CHECK(without.pixelsLeftOut == 1);
    CHECK(without.pixelValues == (kWidth * kHeight - 1) * 3);
}

TEST_CASE("statistical comparison: without variance (point lights) the floor and the reference's error remain") {
    // Four equal replicates of 0.5: variance 0, so the floor applies, 0.01 x the reference's
    // mean per sample, 0.01 x 0.5005 / sqrt(4) = 0.0025 per pixel mean.
    ReplicateStatistics constant;
    for (int k = 0; k < 4; ++k) constant.add(filled(0.5f));
    CHECK(compareStatistically(constant, filled(0.5f)).passes());
    // 0.1 % high: pixel z = -5e-4 / sqrt(0.0025^2 + (2.5e-3 x 0.5005)^2) = -0.18, region z =
    // -5e-4 / sqrt((0.005005 / 4)^2 + (5e-4 x 0.5005)^2) = -0.39.
    CHECK(compareStatistically(constant, filled(0.5f * 1.001f)).passes());
    // 5 % high: pixel z = -0.025 / sqrt(0.002625^2 + (2.5e-3 x 0.525)^2) = -8.5 and region
    // z = -0.025 / sqrt(0.0013125^2 + (5e-4 x 0.525)^2) = -18.7: both families fail.
    StatisticalComparison high = compareStatistically(constant, filled(0.5f * 1.05f));
    CHECK(high.regionFailures() == 36);
    CHECK(high.pixelFailures == kWidth * kHeight * 3);
    CHECK(high.worstPixelZ == doctest::Approx(-8.52).epsilon(2e-3));
    // Zero against zero passes (the floor of an all-black reference is 0); a light where the
    // reference has none fails.
    ReplicateStatistics dark;
    dark.add(filled(0.0f));
    dark.add(filled(0.0f));
    CHECK(compareStatistically(dark, filled(0.0f)).passes());
    CHECK_FALSE(compareStatistically(constant, filled(0.0f)).passes());
}

TEST_CASE("statistical comparison: a pixel whose samples happen to be equal borrows the variance around it") {
    // Every pixel alternates 1.1, 0.9 (variance 0.01333) but (2, 2), which is 1 four times.
    ReplicateStatistics ours;
    for (int k = 0; k < 4; ++k) {
        Image replicate = filled(k % 2 ? 0.9f : 1.1f);
        setPixel(replicate, 2, 2, 1.0f);
        ours.add(replicate);
    }
    Image reference = filled(1.0f);
    setPixel(reference, 2, 2, 1.2f);
    // With its own variance 0 it would be z = -0.2 / (2.5e-3 x 1.2) = -67. Its 3 x 3
    // neighbourhood has 8 pixels with a variance, fewer than 9; the 5 x 5 one has 24, mean
    // variance 24/25 x 0.01333 = 0.0128: z = -0.2 / sqrt(0.0128 / 4 + (3e-3)^2) = -3.53, inside
    // the threshold of 3.97.
    StatisticalComparison c = compareStatistically(ours, reference);
    CHECK(c.pixelFailures == 0);
    CHECK(c.worstPixelZ == doctest::Approx(-3.53).epsilon(2e-3));
}

TEST_CASE("statistical comparison: a NaN or infinite reference pixel fails, mismatched sizes are refused") {
    ReplicateStatistics ours = alternating();
    Image reference = filled(1.0f);
    reference.at(0, 0, 0) = std::numeric_limits<float>::quiet_NaN();
    reference.at(7, 5, 2) = std::numeric_limits<float>::infinity();
    StatisticalComparison c = compareStatistically(ours, reference);
    CHECK(c.pixelFailures == 2);
    CHECK(c.regionFailures() == 2);
    CHECK_THROWS_AS(compareStatistically(ours, Image(4, 4, 3)), Error);
    CHECK_THROWS_AS(compareStatistically(ours, filled(1.0f), std::vector<uint8_t>(3, 0)), Error);
    ReplicateStatistics one;
    one.add(filled(1.0f));
    CHECK_THROWS_AS(compareStatistically(one, filled(1.0f)), Error);
}

TEST_CASE("edge pixels: the column a silhouette crosses, and no other") {
    // Camera at the origin looking down -z, yfov = 2 atan(0.5), so |D| = 1 and |R| = 8/6. A
    // quad in z = -3 ends at x = 0.125: film x = 8 (0.125 / (3 x 8/6) + 0.5) = 4.25, inside
    // pixel column 4 ([4, 5)): its centre (4.5) misses, its left corners hit. The view spans
    // |x| <= 2, |y| <= 1.5 there, so the quad's diagonal (x < -4) is out of it.
    Scene scene;
    scene.triangles.positions = {{-10, -10, -3}, {0.125f, -10, -3}, {0.125f, 10, -3}, {-10, 10, -3}};
    scene.triangles.indices = {{0, 1, 2}, {0, 2, 3}};
    scene.triangles.material = {0, 0};
    scene.triangles.smooth = {0, 0};
    scene.materials = {Material{"grey", Vec3(0.5f), Vec3(0.0f)}};
    Camera camera;
    camera.yfov = 2.0 * std::atan(0.5);
    PrimitiveSet primitives(scene);
    auto accelerator = makeAccelerator(AcceleratorSpec{"brute"});
    accelerator->build(primitives);
    std::vector<uint8_t> edge = findEdgePixels(scene, camera, *accelerator, kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            CHECK((edge[y * kWidth + x] != 0) == (x == 4));
        }
}
