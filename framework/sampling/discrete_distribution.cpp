#include "framework/sampling/discrete_distribution.h"

#include <algorithm>

namespace rtlab {

DiscreteDistribution::DiscreteDistribution(std::span<const double> weights) {
    cdf_.reserve(weights.size() + 1);
    cdf_.push_back(0.0);
    for (double w : weights) cdf_.push_back(cdf_.back() + w);
}

size_t DiscreteDistribution::sample(float u, float* probability) const {
    double target = static_cast<double>(u) * total();
    // The first cdf entry above the target closes the chosen item's interval; an item of
    // weight 0 has an empty interval and is never chosen. u < 1 keeps the target below the
    // total after rounding (u <= 1 - 2^-24, far from 1 in double), so an entry is found.
    size_t i = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()) - 1;
    *probability = this->probability(i);
    return i;
}

float DiscreteDistribution::probability(size_t i) const {
    return static_cast<float>((cdf_[i + 1] - cdf_[i]) / total());
}

}  // namespace rtlab
