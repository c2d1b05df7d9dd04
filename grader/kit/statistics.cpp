#include "grader/kit/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rtlab::grader {
namespace {

constexpr double kRelativeAccuracy = 1e-15;
constexpr int kMaxIterations = 10000;

// x^a e^-x / Gamma(a), the factor both expansions share, in logarithms against overflow.
double gammaPrefactor(double a, double x) { return std::exp(a * std::log(x) - x - std::lgamma(a)); }

// P(a, x) = sum_n x^n / (a (a + 1) ... (a + n)) times the prefactor: converges fast for x < a + 1.
double lowerBySeries(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < kMaxIterations && std::abs(term) > std::abs(sum) * kRelativeAccuracy; ++n) {
        term *= x / (a + n);
        sum += term;
    }
    return sum * gammaPrefactor(a, x);
}

// Q(a, x) = prefactor / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) / (x + 5 - a - ...))),
// evaluated by Lentz's method: converges fast for x > a + 1.
double upperByContinuedFraction(double a, double x) {
    const double tiny = std::numeric_limits<double>::min() / kRelativeAccuracy;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double factor = d * c;
        h *= factor;
        if (std::abs(factor - 1.0) < kRelativeAccuracy) break;
    }
    return h * gammaPrefactor(a, x);
}

}  // namespace

double sidakLevel(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

double upperIncompleteGamma(double a, double x) {
    if (!(x > 0.0)) return 1.0;
    return x < a + 1.0 ? 1.0 - lowerBySeries(a, x) : upperByContinuedFraction(a, x);
}

double lowerIncompleteGamma(double a, double x) {
    if (!(x > 0.0)) return 0.0;
    return x < a + 1.0 ? lowerBySeries(a, x) : 1.0 - upperByContinuedFraction(a, x);
}

double chiSquareUpperTail(double chiSquare, int dof) { return upperIncompleteGamma(0.5 * dof, 0.5 * chiSquare); }

double chiSquareLowerTail(double chiSquare, int dof) { return lowerIncompleteGamma(0.5 * dof, 0.5 * chiSquare); }

double normalTwoSidedP(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

ChiSquareResult chiSquareTest(std::span<const double> observed, std::span<const double> expected, double minExpected) {
    ChiSquareResult result;
    std::vector<size_t> order(expected.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pooledObserved = 0.0, pooledExpected = 0.0;
    std::vector<size_t> cells;  // the cells of their own, in increasing expected count
    for (size_t i : order) {
        if (expected[i] <= 0.0) {
            result.outsideObserved += observed[i];
        } else if (expected[i] < minExpected) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            ++result.pooledCells;
        } else {
            cells.push_back(i);
        }
    }
    auto term = [](double o, double e) { return (o - e) * (o - e) / e; };
    double worst = -1.0;
    for (size_t k = 0; k < cells.size(); ++k) {
        size_t i = cells[k];
        double o = observed[i], e = expected[i];
        // A pool still too small joins the smallest cell of its own.
        if (k == 0 && pooledExpected > 0.0 && pooledExpected < minExpected) {
            o += pooledObserved;
            e += pooledExpected;
            pooledExpected = pooledObserved = 0.0;
        }
        result.chiSquare += term(o, e);
        ++result.dof;
        if (term(observed[i], expected[i]) > worst) {
            worst = term(observed[i], expected[i]);
            result.worstCell = i;
        }
    }
    if (pooledExpected > 0.0) {
        result.chiSquare += term(pooledObserved, pooledExpected);
        ++result.dof;
    }
    result.dof -= 1;
    if (result.dof > 0) {
        result.p = chiSquareUpperTail(result.chiSquare, result.dof);
        result.pLower = chiSquareLowerTail(result.chiSquare, result.dof);
    }
    return result;
}

void MeanEstimate::add(double x) {
    ++count;
    double delta = x - mean;
    mean += delta / static_cast<double>(count);
    sumSquaredDeviations += delta * (x - mean);
}

double MeanEstimate::standardError() const { return std::sqrt(variance() / static_cast<double>(count)); }

double varianceStandardError(size_t count, double variance, double fourthCentralMoment) {
    auto n = static_cast<double>(count);
    return std::sqrt(std::max(0.0, fourthCentralMoment - variance * variance * (n - 3.0) / (n - 1.0)) / n);
}

double logLogSlope(std::span<const double> x, std::span<const double> y) {
    double n = static_cast<double>(x.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace rtlab::grader
