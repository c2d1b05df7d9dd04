// The statistics the grader judges Monte Carlo code by (docs/a6-radiometry.md#how-the-grader-checks-it),
// computed here from the raw samples a worker returns: Pearson's chi-square goodness of fit
// with pooled cells, z tests of a mean, the Sidak correction, and the slope of a log-log fit.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace rtlab::grader {

// The per-test level that keeps the family's level at `alpha` over `tests` independent tests:
// 1 - (1 - alpha)^(1/tests) (Sidak).
double sidakLevel(double alpha, int tests);

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularised upper incomplete gamma function (series
// for x < a + 1, Lentz's continued fraction above), and P(a, x) = 1 - Q(a, x); each small one
// computed as itself, never as 1 minus the other: a tail far below 1e-16 keeps its digits.
double upperIncompleteGamma(double a, double x);
double lowerIncompleteGamma(double a, double x);
// P(X >= chiSquare) and P(X <= chiSquare) for X chi-square distributed with `dof` degrees of
// freedom: small for a fit too bad, and for a fit too good to come from independent samples.
double chiSquareUpperTail(double chiSquare, int dof);
double chiSquareLowerTail(double chiSquare, int dof);
// P(|Z| >= |z|) for a standard normal Z.
double normalTwoSidedP(double z);

struct ChiSquareResult {
    double chiSquare = 0.0;
    int dof = 0;
    double p = 1.0;       // P(X >= chiSquare): small when the samples miss the distribution
    double pLower = 1.0;  // P(X <= chiSquare): small when they fit it better than chance would
    size_t pooledCells = 0;       // cells of expected count < minExpected, summed into one
    double outsideObserved = 0.0;  // samples in cells of expected count 0
    size_t worstCell = 0;          // the cell with the largest (O - E)^2 / E
};

// Pearson's test of observed against expected counts (same total). Cells expecting fewer than
// minExpected samples are pooled into one cell (and that one into the smallest other cell if it
// still expects fewer), as pbrt-v3 and Mitsuba do; cells expecting none are left out of the sum
// and their samples reported in outsideObserved. dof = cells used - 1.
ChiSquareResult chiSquareTest(std::span<const double> observed, std::span<const double> expected, double minExpected = 5.0);

// Mean and standard error of a sample, in one pass (Welford).
struct MeanEstimate {
    size_t count = 0;
    double mean = 0.0;
    double sumSquaredDeviations = 0.0;

    void add(double x);
    double variance() const { return count > 1 ? sumSquaredDeviations / static_cast<double>(count - 1) : 0.0; }
    double standardError() const;
};

// The standard error of the variance s^2 (Bessel-corrected) of n values drawn from a
// distribution of variance sigma^2 and fourth central moment mu4:
// Var(s^2) = (mu4 - sigma^4 (n - 3) / (n - 1)) / n. s^2 is nearly normal for large n when mu4
// is finite, so (s^2 - sigma^2) / this is a z statistic.
double varianceStandardError(size_t n, double variance, double fourthCentralMoment);

// The least-squares slope of log(y) against log(x).
double logLogSlope(std::span<const double> x, std::span<const double> y);

}  // namespace rtlab::grader
