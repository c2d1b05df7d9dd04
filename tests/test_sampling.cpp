// framework/sampling: stratified samples (one per stratum, in [0, 1), shuffled), unbiased
// indices, and picking by weight (docs/conventions.md#sampling).
#include "framework/sampling/discrete_distribution.h"
#include "framework/sampling/stratified.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

using namespace rtlab;

TEST_CASE("sampling: the strata grid of n samples") {
    struct Case {
        int n, columns, rows;
    };
    // rows = the largest divisor of n not above sqrt(n), columns = n / rows.
    for (Case c : {Case{1, 1, 1}, Case{2, 2, 1}, Case{4, 2, 2}, Case{6, 3, 2}, Case{7, 7, 1}, Case{8, 4, 2}, Case{12, 4, 3},
                   Case{16, 4, 4}, Case{1024, 32, 32}}) {
        CAPTURE(c.n);
        StrataGrid grid = strataGrid(c.n);
        CHECK(grid.columns == c.columns);
        CHECK(grid.rows == c.rows);
    }
}

TEST_CASE("sampling: one stratified value per stratum, in [0, 1), in a shuffled order") {
    Pcg32 rng(5, 1);
    for (int n : {1, 3, 10, 64}) {
        CAPTURE(n);
        std::vector<float> values(static_cast<size_t>(n));
        stratified1D(rng, values);
        std::vector<int> hits(static_cast<size_t>(n), 0);
        for (float v : values) {
            REQUIRE((v >= 0.0f && v < 1.0f));
            ++hits[static_cast<size_t>(v * n)];
        }
        CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
    }
    std::vector<Vec2> points(12);
    stratified2D(rng, points);
    std::vector<int> hits(12, 0);  // 4 columns x 3 rows
    for (Vec2 p : points) {
        REQUIRE((p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f));
        ++hits[static_cast<size_t>(p.y * 3) * 4 + static_cast<size_t>(p.x * 4)];
    }
    CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
    // Shuffled: 64 values of 1D strata in increasing order would happen once in 64!.
    std::vector<float> many(64);
    stratified1D(rng, many);
    CHECK_FALSE(std::is_sorted(many.begin(), many.end()));
}

TEST_CASE("sampling: uniformIndex stays in range and covers it evenly") {
    Pcg32 rng(9, 2);
    std::vector<int> counts(3, 0);
    for (int i = 0; i < 30000; ++i) {
        uint32_t k = uniformIndex(rng, 3);
        REQUIRE(k < 3);
        ++counts[k];
    }
    // 10000 expected each; the standard deviation is 82.
    for (int c : counts) CHECK(std::abs(c - 10000) < 400);
    CHECK(uniformIndex(rng, 1) == 0);
}

TEST_CASE("sampling: a discrete distribution picks by weight and never an item of weight 0") {
    std::vector<double> weights{1.0, 0.0, 3.0};
    DiscreteDistribution pick(weights);
    CHECK(pick.size() == 3);
    CHECK(pick.total() == 4.0);
    float probability = 0.0f;
    // cdf 0, 1, 1, 4: u * 4 in [0, 1) picks item 0, in [1, 4) item 2.
    CHECK(pick.sample(0.0f, &probability) == 0);
    CHECK(probability == 0.25f);
    CHECK(pick.sample(0.2499f, &probability) == 0);
    CHECK(pick.sample(0.25f, &probability) == 2);
    CHECK(probability == 0.75f);
    CHECK(pick.sample(kOneMinusEpsilon, &probability) == 2);
    CHECK(pick.probability(1) == 0.0f);
}
