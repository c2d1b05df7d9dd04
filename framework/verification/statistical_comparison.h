// Our Monte Carlo render (replicates.h) against a near-exact reference, a Blender Cycles render
// at high spp (docs/verification.md#statistical-comparison). Two families of z tests, each at
// family level alpha with the Sidak correction over its tests:
//  - region means: the image cut into regionsX x regionsY rectangles, per channel; our mean's
//    standard error from the pixels' replicate variances (pixels draw from independent
//    streams), the reference's own error bounded by referenceRegionError relative;
//  - pixels: every pixel channel, our standard error from its replicates, the reference's
//    bounded by referencePixelError relative; at most allowedPixelFailures of them may fail.
// Our variance of a pixel value is the largest of its own over the replicates, the mean over
// the smallest square around it in which 9 pixels have a variance (half-size 1 to 16), and a
// floor: K samples that all miss a rarely reached light have variance 0, which would make a
// correct estimator fail.
// Cycles' noise is not i.i.d. (its sampler is stratified), so it gives no variance to test
// with: the reference's error enters only as those measured bounds. Pixels flagged in leftOut
// (edge_pixels.h: an edge crosses them) take part in neither family.
#pragma once

#include "framework/render/image.h"
#include "framework/verification/replicates.h"

#include <cstdint>
#include <vector>

namespace rtlab {

struct StatisticalTolerances {
    double alpha = 0.01;
    int regionsX = 4;
    int regionsY = 3;
    // One standard deviation of the reference's error, relative. Cycles at 512 spp against
    // Lambert's contour integral (closed-form scene, emitters cut to edges of 0.25 to 1):
    // region means within 4.3e-4, pixels 0.9e-3 to 2.4e-3 rms (docs/verification.md).
    double referenceRegionError = 5e-4;
    double referencePixelError = 2.5e-3;
    // The smallest standard deviation of one of our samples, relative to the reference's mean
    // over the compared pixels: where even a 33 x 33 neighbourhood's samples all miss a light
    // (a cosine estimator at the horizon), values this far below the image's scale are not
    // judged by variance 0. An absolute floor as Mitsuba 3's (1e-4 on the variance) and
    // Nori's (1e-5) tests have.
    double sampleDeviationFloor = 0.01;
    // The share of pixel values that may fail: the tails of a mean of a few hits are heavier
    // than normal ones; Cycles is biased where a receiver is close to an emitter's plane
    // (docs/verification.md#statistical-comparison).
    double allowedPixelFailures = 0.002;
};

struct RegionResult {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1)
    int channel = 0;
    int pixels = 0;  // those not left out
    double ours = 0.0;
    double standardError = 0.0;  // of ours
    double reference = 0.0;
    double z = 0.0;  // (ours - reference) / sqrt(standardError^2 + (referenceRegionError reference)^2)
    bool passes = true;
};

struct StatisticalComparison {
    int replicates = 0;
    StatisticalTolerances tolerances;
    std::vector<RegionResult> regions;
    double regionLevel = 0.0;  // the per-test level after Sidak
    uint64_t pixelsLeftOut = 0;  // edge pixels
    uint64_t pixelValues = 0;    // pixel channels tested
    uint64_t pixelFailures = 0;
    double pixelLevel = 0.0;
    double worstPixelZ = 0.0;  // the largest |z| of a pixel channel, and where
    int worstX = 0, worstY = 0;

    int regionFailures() const;
    double pixelFailureShare() const { return pixelValues ? double(pixelFailures) / double(pixelValues) : 0.0; }
    bool passes() const {
        return regionFailures() == 0 && pixelFailureShare() <= tolerances.allowedPixelFailures;
    }
};

// Throws rtlab::Error when the sizes differ (of the images or of leftOut, which is empty or one
// flag per pixel), the reference has fewer channels than ours, or fewer than two replicates
// were added.
StatisticalComparison compareStatistically(const ReplicateStatistics& ours, const Image& reference,
                                           const std::vector<uint8_t>& leftOut = {},
                                           const StatisticalTolerances& tolerances = {});

}  // namespace rtlab
