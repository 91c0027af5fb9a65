#include "core/gauss_legendre.h"

#include <cmath>
#include <stdexcept>
#include "core/math.h"

namespace columba {

GaussLegendreRule gaussLegendre(int n) {
  if (n < 1) throw std::invalid_argument("a Gauss-Legendre rule needs at least one node");
  GaussLegendreRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // i-th root of P_n on [-1, 1], counted from the right.
    double x = std::cos(kPiDouble * (i + 0.75) / (n + 0.5)), derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      // Recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}.
      double p0 = 1.0, p1 = x;
      for (int k = 1; k < n; ++k) {
        double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      // P_n' = n (x P_n - P_{n-1}) / (x^2 - 1).
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    // Map [-1, 1] to [0, 1]; roots come out descending, store them ascending.
    rule.nodes[n - 1 - i] = 0.5 * (x + 1.0);
    rule.weights[n - 1 - i] = 0.5 * weight;
  }
  return rule;
}

}  // namespace columba
