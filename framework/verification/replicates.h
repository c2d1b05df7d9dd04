// A Monte Carlo render repeated with K seeds (replicates) and summarised per pixel: the mean and
// the sample variance over the replicates. At one sample per pixel every replicate takes its
// pixel's one camera ray through the pixel centre and one light sample from its own random
// stream (docs/conventions.md#sampling), so a pixel's K values are independent draws of the
// estimator, and its variance over them is the estimator's own, whatever its sampling.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/render/image.h"
#include "framework/render/renderer.h"
#include "framework/scene/scene.h"

#include <cstdint>
#include <vector>

namespace rtlab {

class ReplicateStatistics {
public:
    // Adds one replicate (Welford's update per pixel channel). Throws rtlab::Error when its size
    // or channel count differs from the first one's.
    void add(const Image& replicate);

    int replicates() const { return count_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    // Per value (y * width + x) * channels + c, as Image::pixels.
    double mean(size_t value) const { return mean_[value]; }
    double variance(size_t value) const { return count_ > 1 ? squaredDeviations_[value] / (count_ - 1) : 0.0; }
    Image meanImage() const;

private:
    int count_ = 0;
    int width_ = 0;
    int height_ = 0;
    int channels_ = 0;
    std::vector<double> mean_;
    std::vector<double> squaredDeviations_;
};

// Renders `replicates` images of settings' size, one sample per pixel each, with the seeds
// firstSeed, firstSeed + 1, ... (settings.samplesPerPixel and settings.seed are replaced).
ReplicateStatistics renderReplicates(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                                     RenderSettings settings, int replicates, uint64_t firstSeed = 0);

}  // namespace rtlab
