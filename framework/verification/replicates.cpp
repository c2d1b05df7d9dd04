#include "framework/verification/replicates.h"

#include "framework/core/error.h"

#include <string>

namespace rtlab {

void ReplicateStatistics::add(const Image& replicate) {
    if (count_ == 0) {
        width_ = replicate.width;
        height_ = replicate.height;
        channels_ = replicate.channels;
        mean_.assign(replicate.pixels.size(), 0.0);
        squaredDeviations_.assign(replicate.pixels.size(), 0.0);
    } else if (replicate.width != width_ || replicate.height != height_ || replicate.channels != channels_) {
        throw Error("replicate " + std::to_string(count_ + 1) + " is " + std::to_string(replicate.width) + "x" +
                    std::to_string(replicate.height) + " with " + std::to_string(replicate.channels) +
                    " channels, the first was " + std::to_string(width_) + "x" + std::to_string(height_) + " with " +
                    std::to_string(channels_));
    }
    ++count_;
    for (size_t i = 0; i < mean_.size(); ++i) {
        double x = replicate.pixels[i];
        double delta = x - mean_[i];
        mean_[i] += delta / count_;
        squaredDeviations_[i] += delta * (x - mean_[i]);
    }
}

Image ReplicateStatistics::meanImage() const {
    Image image(width_, height_, channels_);
    for (size_t i = 0; i < mean_.size(); ++i) image.pixels[i] = static_cast<float>(mean_[i]);
    return image;
}

ReplicateStatistics renderReplicates(const Scene& scene, const Camera& camera, const Accelerator& accelerator,
                                     RenderSettings settings, int replicates, uint64_t firstSeed) {
    if (replicates < 2) throw Error("replicates: " + std::to_string(replicates) + " is fewer than 2 (no variance)");
    settings.samplesPerPixel = 1;
    settings.aovs.clear();
    Renderer renderer(scene, camera, accelerator);
    ReplicateStatistics statistics;
    for (int k = 0; k < replicates; ++k) {
        settings.seed = firstSeed + static_cast<uint64_t>(k);
        statistics.add(renderer.render(settings).colour);
    }
    return statistics;
}

}  // namespace rtlab
