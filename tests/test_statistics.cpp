// grader/kit/statistics: the tails of the chi-square and normal distributions against printed
// tables, the Sidak level, pooling in Pearson's test, and the log-log slope.
#include "grader/kit/statistics.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace rtlab::grader;

TEST_CASE("statistics: chi-square tails at the critical values of the tables") {
    // Upper 1 % and 5 % points of the chi-square distribution (NIST/SEMATECH e-Handbook,
    // table 1.3.6.7.4; Abramowitz and Stegun 26.4): P(X >= c) = alpha.
    struct Point {
        int dof;
        double critical, alpha;
    };
    for (Point p : {Point{1, 3.841, 0.05}, Point{1, 6.635, 0.01}, Point{10, 23.209, 0.01}, Point{20, 31.410, 0.05},
                    Point{100, 135.807, 0.01}, Point{100, 124.342, 0.05}}) {
        CAPTURE(p.dof);
        CAPTURE(p.critical);
        CHECK(chiSquareUpperTail(p.critical, p.dof) == doctest::Approx(p.alpha).epsilon(2e-3));
    }
    // Two degrees of freedom: the tail is exp(-x / 2) exactly.
    CHECK(chiSquareUpperTail(7.0, 2) == doctest::Approx(std::exp(-3.5)).epsilon(1e-12));
    CHECK(chiSquareUpperTail(0.0, 5) == 1.0);
    // Both expansions meet at x = a + 1 (series below, continued fraction above).
    CHECK(upperIncompleteGamma(4.0, 4.999999) == doctest::Approx(upperIncompleteGamma(4.0, 5.000001)).epsilon(1e-5));
}

TEST_CASE("statistics: normal tails and the Sidak level") {
    CHECK(normalTwoSidedP(2.5758293) == doctest::Approx(0.01).epsilon(1e-6));
    CHECK(normalTwoSidedP(-1.959964) == doctest::Approx(0.05).epsilon(1e-6));
    CHECK(normalTwoSidedP(0.0) == 1.0);
    CHECK(sidakLevel(0.01, 1) == doctest::Approx(0.01));
    // 1 - 0.99^(1/5) = 0.0020081...
    CHECK(sidakLevel(0.01, 5) == doctest::Approx(0.00200808).epsilon(1e-5));
}

TEST_CASE("statistics: Pearson's test pools cells expecting fewer than 5 and reports empty ones") {
    // Expected 2, 2, 2 (pooled: 6), 50, 44, 0; observed 3, 1, 4, 45, 47, 1.
    std::vector<double> expected{2, 2, 2, 50, 44, 0}, observed{3, 1, 4, 45, 47, 1};
    ChiSquareResult r = chiSquareTest(observed, expected);
    CHECK(r.pooledCells == 3);
    CHECK(r.outsideObserved == 1.0);
    // (8 - 6)^2 / 6 + (45 - 50)^2 / 50 + (47 - 44)^2 / 44, three cells: 2 dof.
    CHECK(r.chiSquare == doctest::Approx(4.0 / 6 + 25.0 / 50 + 9.0 / 44));
    CHECK(r.dof == 2);
    CHECK(r.p == doctest::Approx(std::exp(-r.chiSquare / 2)));
    CHECK(r.worstCell == 3);
    // A pool that still expects fewer than 5 joins the smallest cell of its own.
    std::vector<double> few{1, 1, 20, 30}, seen{2, 0, 19, 31};
    ChiSquareResult small = chiSquareTest(seen, few);
    CHECK(small.dof == 1);
    CHECK(small.chiSquare == doctest::Approx(1.0 / 22 + 1.0 / 30));
}

TEST_CASE("statistics: mean, standard error and the log-log slope") {
    MeanEstimate m;
    for (double x : {1.0, 2.0, 3.0, 4.0}) m.add(x);
    CHECK(m.mean == 2.5);
    CHECK(m.variance() == doctest::Approx(5.0 / 3.0));
    CHECK(m.standardError() == doctest::Approx(std::sqrt(5.0 / 12.0)));
    std::vector<double> n{16, 64, 256, 1024}, error;
    for (double v : n) error.push_back(3.0 / std::sqrt(v));
    CHECK(logLogSlope(n, error) == doctest::Approx(-0.5));
}

TEST_CASE("statistics: the lower chi-square tail judges a fit too good to be random") {
    // Two degrees of freedom: P(X <= x) = 1 - exp(-x / 2), kept exact also far below 1e-16.
    CHECK(chiSquareLowerTail(0.1, 2) == doctest::Approx(-std::expm1(-0.05)).epsilon(1e-12));
    CHECK(chiSquareLowerTail(1e-20, 2) == doctest::Approx(5e-21).epsilon(1e-9));
    // Lower 1 % and 5 % points (NIST/SEMATECH e-Handbook, table 1.3.6.7.4): P(X <= c) = alpha.
    CHECK(chiSquareLowerTail(70.065, 100) == doctest::Approx(0.01).epsilon(2e-3));
    CHECK(chiSquareLowerTail(3.940, 10) == doctest::Approx(0.05).epsilon(2e-3));
    // Both tails together make one.
    CHECK(chiSquareLowerTail(575.0, 575) + chiSquareUpperTail(575.0, 575) == doctest::Approx(1.0).epsilon(1e-12));
    // Counts that meet every cell's expectation exactly: chi^2 = 0, which independent samples
    // reach with probability 0.
    std::vector<double> expected{50, 30, 20}, observed{50, 30, 20};
    ChiSquareResult quota = chiSquareTest(observed, expected);
    CHECK(quota.chiSquare == 0.0);
    CHECK(quota.p == 1.0);
    CHECK(quota.pLower == 0.0);
}

TEST_CASE("statistics: the standard error of a sample variance") {
    // Normal values: mu4 = 3 sigma^4, and Var(s^2) = 2 sigma^4 / (n - 1) exactly.
    CHECK(varianceStandardError(101, 4.0, 48.0) == doctest::Approx(std::sqrt(2.0 * 16.0 / 100.0)).epsilon(1e-12));
    // Values +-1 with equal odds: mu4 = sigma^4 = 1, Var(s^2) = (1 - (n - 3) / (n - 1)) / n = 2 / (n (n - 1)).
    CHECK(varianceStandardError(11, 1.0, 1.0) == doctest::Approx(std::sqrt(2.0 / 110.0)).epsilon(1e-12));
}
