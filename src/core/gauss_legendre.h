#pragma once
// Gauss–Legendre quadrature on [0, 1]: n nodes integrate polynomials up to degree 2n - 1 exactly.
#include <vector>

namespace columba {

struct GaussLegendreRule {
  std::vector<double> nodes;    // in (0, 1), ascending
  std::vector<double> weights;  // sum to 1
};

// Nodes are the roots of the Legendre polynomial P_n, found by Newton's method from
// Chebyshev-like starting points (accurate to double precision for any practical n).
GaussLegendreRule gaussLegendre(int n);

}  // namespace columba
