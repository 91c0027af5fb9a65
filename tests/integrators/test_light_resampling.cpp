// resampleLights: the choice among emitter candidates, its chi-square test, and the unbiasedness
// of the resampled estimate on a discrete integral with a closed form.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include "core/rng.h"
#include "integrators/direct_light.h"
#include "support/chi_square.h"

using namespace columba;
using namespace columba::testing;

TEST(LightResampling, ChoosesInProportionToTheRatios) {
  const std::array<float, 5> ratios = {1.0f, 0.0f, 3.0f, 2.0f, 0.5f};
  const float total = 6.5f;
  const int draws = 20000;
  std::vector<double> observed(ratios.size(), 0.0), expected(ratios.size());
  for (size_t k = 0; k < ratios.size(); ++k) expected[k] = draws * double(ratios[k]) / total;
  PCG32 rng(3);
  for (int i = 0; i < draws; ++i) {
    std::optional<ResampledLight> chosen = resampleLights(ratios.data(), int(ratios.size()), rng.nextFloat());
    ASSERT_TRUE(chosen);
    ASSERT_GT(ratios[size_t(chosen->index)], 0.0f) << "a candidate of ratio 0 was chosen";
    // mean(r) / r_chosen
    ASSERT_FLOAT_EQ(chosen->weight, total / 5.0f / ratios[size_t(chosen->index)]);
    observed[size_t(chosen->index)] += 1.0;
  }
  const ChiSquareResult result = chiSquareTest(observed, expected);
  EXPECT_GT(result.pValue, 0.01) << result.message;
}

TEST(LightResampling, NoCandidateWithAContributionChoosesNothing) {
  const std::array<float, 3> zeros = {0.0f, 0.0f, 0.0f};
  EXPECT_FALSE(resampleLights(zeros.data(), 3, 0.5f));
  const std::array<float, 3> one = {0.0f, 2.0f, 0.0f};
  for (float u : {0.0f, 0.5f, 0.9999f}) {
    std::optional<ResampledLight> chosen = resampleLights(one.data(), 3, u);
    ASSERT_TRUE(chosen);
    EXPECT_EQ(chosen->index, 1);
    EXPECT_FLOAT_EQ(chosen->weight, 1.0f / 3.0f);  // the two empty draws count in the mean
  }
}

// The sum of g over five points, estimated by drawing 3 candidates from p (point 1 stands for a
// failed draw: g = 0 and ratio 0) and weighing the chosen one's g / p by resampleLights' weight,
// as next-event estimation does with f Le V / pdf. With any target (the ratio's numerator)
// positive wherever g is, the estimate is unbiased; with the target g itself, every chosen
// candidate gives mean(r), whose variance is Var(g / p) / 3 in closed form.
TEST(LightResampling, TheResampledEstimateIsUnbiased) {
  constexpr int kCandidates = 3;
  const std::array<double, 5> p = {0.1, 0.2, 0.3, 0.25, 0.15}, g = {2.0, 0.0, 1.0, 5.0, 3.0};
  const double exact = 11.0;
  struct Moments {
    double mean, variance, standardError;
  };
  auto estimate = [&](const std::array<double, 5>& target, uint64_t seed) {
    PCG32 rng(seed);
    auto draw = [&] {
      double u = rng.nextFloat(), below = 0.0;
      for (size_t k = 0; k < p.size(); ++k)
        if (u < (below += p[k])) return k;
      return p.size() - 1;
    };
    const int trials = 400000;
    double sum = 0.0, sumSquares = 0.0;
    for (int t = 0; t < trials; ++t) {
      std::array<size_t, kCandidates> drawn;
      std::array<float, kCandidates> ratios;
      for (size_t c = 0; c < drawn.size(); ++c) {
        drawn[c] = draw();
        ratios[c] = float(target[drawn[c]] / p[drawn[c]]);
      }
      double value = 0.0;
      if (std::optional<ResampledLight> chosen = resampleLights(ratios.data(), kCandidates, rng.nextFloat())) {
        const size_t k = drawn[size_t(chosen->index)];
        value = g[k] / p[k] * chosen->weight;
      }
      sum += value;
      sumSquares += value * value;
    }
    const double mean = sum / trials, variance = sumSquares / trials - mean * mean;
    return Moments{mean, variance, std::sqrt(variance / trials)};
  };
  const Moments other = estimate({1.0, 0.0, 4.0, 2.0, 1.0}, 11);
  EXPECT_NEAR(other.mean, exact, 5.0 * other.standardError);
  const Moments ideal = estimate(g, 12);
  EXPECT_NEAR(ideal.mean, exact, 5.0 * ideal.standardError);
  double plainSquares = 0.0;  // E[(g / p)^2]
  for (size_t k = 0; k < p.size(); ++k) plainSquares += g[k] * g[k] / p[k];
  EXPECT_NEAR(ideal.variance, (plainSquares - exact * exact) / kCandidates, 0.05 * ideal.variance);
}
