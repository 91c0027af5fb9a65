#pragma once
// Chi-square goodness-of-fit tests for sampling routines: histogram the samples over bins,
// integrate the claimed density over the same bins, and compare (as Mitsuba's test suite does).
#include <functional>
#include <optional>
#include <string>
#include <vector>
#include "core/rng.h"
#include "core/vector.h"

namespace columba::testing {

struct ChiSquareResult {
  double statistic = 0.0;
  int degreesOfFreedom = 0;
  double pValue = 0.0;
  std::string message;  // counts, pooling and the p-value, for the test log
};

// Regularised upper incomplete gamma function Q(a, x); the chi-square survival function is
// Q(dof / 2, statistic / 2).
double regularizedGammaQ(double a, double x);

// Pearson's test of observed counts against expected counts. Bins expected to hold fewer than
// `minExpected` (zero-density bins included) are pooled into one, so a few samples in a sliver
// the bin quadrature cannot see do not fail the test, while many samples where the density is
// zero make that pooled bin fail it.
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected = 5.0);

// Draws `sampleCount` directions from `sample` (nullopt = no direction, e.g. absorbed or a
// delta component) and compares them with `pdf` (solid-angle density over the whole sphere)
// on a grid of thetaBins x phiBins bins equal in area (cos theta x phi). Each bin's expected
// count is integrated with `quadrature` x `quadrature` midpoints.
ChiSquareResult chiSquareDirectionTest(const std::function<std::optional<Vec3>(PCG32&)>& sample,
                                       const std::function<double(const Vec3&)>& pdf, int sampleCount,
                                       int thetaBins = 20, int phiBins = 40, int quadrature = 16, uint64_t seed = 1);

}  // namespace columba::testing
