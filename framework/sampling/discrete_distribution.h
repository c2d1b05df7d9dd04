// Picking one of several items with probability proportional to a weight (the renderer picks
// the light to sample by its power: docs/conventions.md#lights-and-units).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace rtlab {

class DiscreteDistribution {
public:
    DiscreteDistribution() = default;
    // Weights must be finite and not negative; items of weight 0 are never picked.
    explicit DiscreteDistribution(std::span<const double> weights);

    size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
    double total() const { return cdf_.empty() ? 0.0 : cdf_.back(); }
    // The item i with cdf_i <= u * total < cdf_{i+1} for u in [0, 1), and its probability
    // weight_i / total. Only for a distribution of positive total.
    size_t sample(float u, float* probability) const;
    float probability(size_t i) const;

private:
    std::vector<double> cdf_;  // cdf_[0] = 0, cdf_[i + 1] = cdf_[i] + weight_i
};

}  // namespace rtlab
