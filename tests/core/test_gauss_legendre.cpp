#include <gtest/gtest.h>

#include <cmath>
#include "core/gauss_legendre.h"

using namespace columba;

TEST(GaussLegendre, IntegratesPolynomialsUpToDegree2nMinus1Exactly) {
  for (int n = 1; n <= 24; ++n) {
    GaussLegendreRule rule = gaussLegendre(n);
    ASSERT_EQ(int(rule.nodes.size()), n);
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], degree);
      EXPECT_NEAR(sum, 1.0 / (degree + 1), 1e-13) << n << " nodes, degree " << degree;
    }
    // ... and no further: x^(2n) is off (by an amount that shrinks fast with n).
    if (n <= 6) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], 2 * n);
      EXPECT_GT(std::abs(sum - 1.0 / (2 * n + 1)), 1e-8) << n;
    }
    for (int i = 1; i < n; ++i) EXPECT_LT(rule.nodes[i - 1], rule.nodes[i]);
  }
}
