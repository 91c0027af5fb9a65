#include "support/chi_square.h"

#include <cmath>
#include <sstream>

namespace columba::testing {

namespace {
// Series for P(a, x), valid for x < a + 1.
double gammaPSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction for Q(a, x) (modified Lentz), valid for x >= a + 1.
double gammaQContinuedFraction(double a, double x) {
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}
}  // namespace

double regularizedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected) {
  ChiSquareResult result;
  std::ostringstream log;
  double pooledObserved = 0, pooledExpected = 0, statistic = 0;
  int bins = 0, pooled = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < minExpected) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
      ++pooled;
    } else {
      statistic += sqr(observed[i] - expected[i]) / expected[i];
      ++bins;
    }
  }
  if (pooledExpected >= minExpected) {
    statistic += sqr(pooledObserved - pooledExpected) / pooledExpected;
    ++bins;
  } else if (pooledObserved > 0) {
    // Too little mass to test on its own: merge into the statistic conservatively as one bin.
    statistic += sqr(pooledObserved - pooledExpected) / std::max(pooledExpected, 1.0);
    ++bins;
  }
  result.statistic = statistic;
  result.degreesOfFreedom = std::max(bins - 1, 1);
  result.pValue = regularizedGammaQ(0.5 * result.degreesOfFreedom, 0.5 * statistic);
  log << "chi2 = " << statistic << ", dof = " << result.degreesOfFreedom << " (" << pooled
      << " sparse bins pooled), p = " << result.pValue;
  result.message = log.str();
  return result;
}

ChiSquareResult chiSquareDirectionTest(const std::function<std::optional<Vec3>(PCG32&)>& sample,
                                       const std::function<double(const Vec3&)>& pdf, int sampleCount, int thetaBins,
                                       int phiBins, int quadrature, uint64_t seed) {
  auto binOf = [&](const Vec3& w) {
    double z = std::clamp(double(w.z), -1.0, 1.0);
    // Directions exactly on a bin boundary (e.g. the horizon) count in the upper bin.
    int ti = std::clamp(int(std::ceil((1.0 - z) * 0.5 * thetaBins)) - 1, 0, thetaBins - 1);
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0) phi += 2.0 * M_PI;
    int pi = std::min(int(phi / (2.0 * M_PI) * phiBins), phiBins - 1);
    return ti * phiBins + pi;
  };
  std::vector<double> observed(size_t(thetaBins) * phiBins, 0.0), expected(observed.size(), 0.0);
  PCG32 rng(seed, 0x5eed);
  for (int i = 0; i < sampleCount; ++i)
    if (auto w = sample(rng); w && isFinite(*w)) observed[binOf(normalize(*w))] += 1.0;

  // Bins are equal-area cells in (z = cos theta, phi): dw = dz dphi. The pdf is integrated on a
  // grid of quadrature x quadrature midpoint cells per bin; cells next to a jump of the pdf
  // (zero against non-zero, or a ratio above 2: a light's silhouette, a pixel edge of an
  // environment map) are integrated again with kRefine x kRefine points, since one midpoint
  // misjudges how much of such a cell the pdf covers.
  constexpr int kRefine = 8;
  const int rows = thetaBins * quadrature, cols = phiBins * quadrature;
  const double dz = 2.0 / rows, dphi = 2.0 * M_PI / cols;
  auto pdfAt = [&](double z, double phi) {
    double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return pdf(Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
  };
  std::vector<double> cell(size_t(rows) * cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) cell[size_t(i) * cols + j] = pdfAt(1.0 - (i + 0.5) * dz, (j + 0.5) * dphi);
  auto jump = [](double a, double b) {
    if ((a > 0.0) != (b > 0.0)) return true;
    return a > 0.0 && (a > 2.0 * b || b > 2.0 * a);
  };
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      double v = cell[size_t(i) * cols + j];
      bool refine = false;
      for (int di = -1; di <= 1 && !refine; ++di)
        for (int dj = -1; dj <= 1 && !refine; ++dj) {
          int ni = i + di, nj = (j + dj + cols) % cols;
          if (ni >= 0 && ni < rows) refine = jump(v, cell[size_t(ni) * cols + nj]);
        }
      if (refine) {
        double sum = 0;
        for (int a = 0; a < kRefine; ++a)
          for (int b = 0; b < kRefine; ++b)
            sum += pdfAt(1.0 - (i + (a + 0.5) / kRefine) * dz, (j + (b + 0.5) / kRefine) * dphi);
        v = sum / (kRefine * kRefine);
      }
      expected[size_t(i / quadrature) * phiBins + j / quadrature] += v * dz * dphi * sampleCount;
    }
  return chiSquareTest(observed, expected);
}

}  // namespace columba::testing
